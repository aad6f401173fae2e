// SPDX-License-Identifier: Apache-2.0
// Top level specular_unit: the protocol of docs/interfaces.md as fixed for the RTL
// (latency L = specular_pkg::unit_latency, docs/pipeline.md#stage-counts; one pixel per
// clock, busy through the last pixel, l + L + 1 clocks per line), zero conditions, writes
// and starts while busy, asynchronous reset, at the single-bank build (roms/build_configs.cmake
// "single", specular::device::Format{}; the default build, a blend, runs in sim_regression and
// test_blend.cpp): its parameters against Format{}, the pixels against C cos^k(a psi) in long double within the
// interpolated ROM 12's error bound, and against the golden model bit for bit.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter header
#include "Vunit.h"
#include "Vunit_specular_unit.h"
#include "Vpipeline_single_specular_pipeline.h"
#pragma GCC diagnostic pop
#include "rtl_harness.hpp"

#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <type_traits>
#include <vector>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

using R = Vunit_specular_unit;  // public parameters (/*verilator public*/)
// Start in cycle s -> first valid pixel in s + L: the start latch, register 8 and the block
// latencies and the stream's output buffer, as rtl/prim/specular_pkg.sv defines them (read through
// sim/specular_pipeline.sv, not from the model under test); the tests measure it.
using P = Vpipeline_single_specular_pipeline;
constexpr int kLatency = static_cast<int>(P::UnitLatency);
constexpr int kBlockLatency = static_cast<int>(P::StartLatchStages + P::AccStages + P::Mul11Stages + P::Rom12Stages +
                                               P::Mul13Stages + P::OutBufStages);
constexpr int kLineOverhead = kLatency + 1;  // start to next accepted start: l + L + 1 cycles

struct Line {
  uint32_t c = 0x4000;  // 0.5
  int32_t psi0 = 0;
  int32_t dpsi = 0;
  uint32_t n = 100;
  uint32_t len = 3;
};

void clear_inputs(Vunit& dut) {
  dut.c_we_i = dut.dpsi_we_i = dut.psi0_we_i = dut.n_we_i = dut.len_we_i = 0;
  dut.start_i = 0;
}

// Writes every register and starts in the same cycle (allowed: the writes apply).
void write_and_start(Vunit& dut, const Line& ln, bool start = true) {
  dut.c_we_i = 1;
  dut.c_i = ln.c;
  dut.dpsi_we_i = 1;
  dut.dpsi_i = static_cast<uint32_t>(ln.dpsi);
  dut.psi0_we_i = 1;
  dut.psi0_i = static_cast<uint32_t>(ln.psi0);
  dut.n_we_i = 1;
  dut.n_i = ln.n;
  dut.len_we_i = 1;
  dut.len_i = ln.len;
  dut.start_i = start;
}

struct Trace {
  std::vector<uint32_t> pixels;
  std::vector<int> valid_cycles;  // cycles (after the start cycle) with valid_o high
  int first_valid = -1;   // cycles after the start cycle
  int busy_first = -1, busy_last = -1;
  bool valid_contiguous = true;
  bool busy_contiguous = true;
  int nonzero_while_invalid = 0;  // intensity_o must read 0 whenever valid_o is low
};

// Cycle 0 = the start cycle (inputs already set by the caller); runs `cycles` cycles.
// `during` is called in every cycle after the start, before eval, to poke inputs.
template <class F>
Trace run_line(Vunit& dut, int cycles, F during) {
  Trace t;
  int last_valid = -2, last_busy = -2;
  for (int c = 0; c < cycles; ++c) {
    if (c > 0) {
      clear_inputs(dut);
      during(c);
    }
    dut.eval();
    if (dut.valid_o) {
      if (t.first_valid < 0) t.first_valid = c;
      else if (last_valid != c - 1) t.valid_contiguous = false;
      last_valid = c;
      t.pixels.push_back(dut.intensity_o);
      t.valid_cycles.push_back(c);
    }
    if (!dut.valid_o && dut.intensity_o != 0) ++t.nonzero_while_invalid;
    if (dut.busy_o) {
      if (t.busy_first < 0) t.busy_first = c;
      else if (last_busy != c - 1) t.busy_contiguous = false;
      last_busy = c;
      t.busy_last = c;
    }
    tick(dut);
  }
  clear_inputs(dut);
  dut.eval();
  return t;
}

Trace run_line(Vunit& dut, int cycles) {
  return run_line(dut, cycles, [](int) {});
}

// Bit b of a packed parameter: an integer up to 64 bits, a VlWide of 32-bit words above.
template <class W>
uint32_t param_bit(const W& w, size_t b) {
  if constexpr (std::is_integral_v<W>) {
    return static_cast<uint32_t>((static_cast<uint64_t>(w) >> b) & 1u);
  } else {
    return (w[b / 32] >> (b % 32)) & 1u;
  }
}

// C * cos^k(0): cos^k(0) = 1 is exact in the interpolated ROM 12, so the peak is C itself.
uint32_t peak_intensity(uint32_t c) { return c; }

// Decoder 10 of the single-bank build, written out by hand: banks k = 1, 2, 3, 4, 6, 8, 12, 16
// serve n = 1 | 2 | 3 | 4 | 5..6 | 7..9 | 10..13 | 14..1000.
int k_of(uint32_t n) {
  if (n <= 4) return static_cast<int>(n);
  if (n <= 6) return 6;
  if (n <= 9) return 8;
  if (n <= 13) return 12;
  return 16;
}

}  // namespace

TEST_CASE("specular_unit at the single build's flags equals device::Format{}", "[rtl][unit]") {
  const specular::device::Format f;
  auto i = [](auto v) { return static_cast<int>(v); };
  CHECK(i(R::CBits) == f.c_bits);
  CHECK(i(R::CFrac) == f.c_frac);
  CHECK(i(R::AngleBits) == f.angle_bits);
  CHECK(i(R::AngleFrac) == f.angle_frac);
  CHECK(i(R::AccBits) == f.acc_bits);
  CHECK(i(R::NBits) == f.n_bits);
  CHECK(i(R::LenBits) == f.len_bits);
  CHECK(i(R::CoefBits) == f.coef_bits);
  CHECK(i(R::CoefFrac) == f.coef_frac);
  CHECK(i(R::PsiMulFrac) == f.psi_mul_frac);
  CHECK(i(R::CosInterp) == (f.cos_interp ? 1 : 0));
  CHECK(i(R::CosAddrBits) == f.cos_addr_bits);
  CHECK(i(R::CosDataBits) == f.cos_data_bits);
  CHECK(i(R::CosDeltaBits) == f.cos_delta_bits);
  CHECK(i(R::CosFracBits) == f.cos_frac_bits);
  CHECK(i(R::NumBanks) == static_cast<int>(f.banks.size()));
  // BankMaxN: NumBanks fields of NBits, bank 0 in the least significant bits; 80 bits wide
  // in this build, so Verilator holds it as a VlWide of 32-bit words.
  REQUIRE(f.bank_max_n.size() * f.n_bits <= 96);
  auto bit = [](size_t b) { return param_bit(R::BankMaxN, b); };
  for (size_t j = 0; j < f.bank_max_n.size(); ++j) {
    uint32_t field = 0;
    for (int b = 0; b < f.n_bits; ++b) field |= bit(j * f.n_bits + static_cast<size_t>(b)) << b;
    INFO("bank " << j);
    CHECK(field == static_cast<uint32_t>(f.bank_max_n[j]));
  }
  // The single build's decoder table, by hand: 1, 2, 3, 4, 6, 9, 13, 1000.
  CHECK(f.bank_max_n == std::vector<int>{1, 2, 3, 4, 6, 9, 13, 1000});
}

TEST_CASE("specular_unit protocol: latency, l+1 pixels, busy, for l = 0..3", "[rtl][unit]") {
  const uint32_t l = GENERATE(0u, 1u, 2u, 3u, 10u, 2047u);  // 2047: counter maximum
  Vunit dut;
  reset(dut);
  clear_inputs(dut);
  dut.eval();
  CHECK(dut.busy_o == 0);
  CHECK(dut.valid_o == 0);
  CHECK(dut.intensity_o == 0);
  Line ln;
  ln.len = l;
  write_and_start(dut, ln);
  const Trace t = run_line(dut, static_cast<int>(l) + kLatency + 6);
  CHECK(kLatency == kBlockLatency);
  CHECK(t.first_valid == kLatency);
  CHECK(t.pixels.size() == l + 1);
  CHECK(t.valid_contiguous);
  CHECK(t.busy_contiguous);
  CHECK(t.busy_first == 1);
  CHECK(t.busy_last == kLatency + static_cast<int>(l));  // through the last pixel
  CHECK(t.nonzero_while_invalid == 0);
  for (uint32_t p : t.pixels) CHECK(p == peak_intensity(ln.c));
}

TEST_CASE("specular_unit accepts the next start in the first idle cycle", "[rtl][unit]") {
  const uint32_t l = GENERATE(0u, 3u);
  Vunit dut;
  reset(dut);
  Line ln;
  ln.len = l;
  write_and_start(dut, ln);
  const int next = static_cast<int>(l) + kLineOverhead;
  // Hold start_i high in every cycle: lines start in cycles 0, l+7, 2(l+7), ...
  const Trace t = run_line(dut, 2 * next + kLatency + 1, [&](int) { dut.start_i = 1; });
  std::vector<int> want;
  for (int line = 0; line < 3; ++line)
    for (int i = 0; i <= static_cast<int>(l); ++i)
      if (line * next + kLatency + i <= 2 * next + kLatency) want.push_back(line * next + kLatency + i);
  CHECK(t.valid_cycles == want);
  CHECK(t.pixels.size() == 2 * (l + 1) + 1);
}

TEST_CASE("specular_unit ignores writes and starts while busy", "[rtl][unit]") {
  Vunit dut;
  reset(dut);
  Line ln;
  ln.len = 5;
  write_and_start(dut, ln);
  // In every busy cycle try to change every register and to restart.
  const Trace t1 = run_line(dut, 5 + kLineOverhead, [&](int c) {
    if (c <= kLatency + 5) {
      Line other{0x1000, 0x12345678, 0x01000000, 0, 1};
      write_and_start(dut, other);
    }
  });
  REQUIRE(t1.pixels.size() == 6);
  for (uint32_t p : t1.pixels) CHECK(p == peak_intensity(ln.c));
  // A plain start reuses the registers of the first line (l included).
  dut.start_i = 1;
  const Trace t2 = run_line(dut, 5 + kLineOverhead + 2);
  REQUIRE(t2.pixels.size() == 6);
  for (uint32_t p : t2.pixels) CHECK(p == peak_intensity(ln.c));
}

TEST_CASE("specular_unit: C x cos^k(0) = C exactly in every bank", "[rtl][unit]") {
  // psi = 0 on the whole line: cos^k(0) = 1 is exact in the interpolated ROM 12, so every
  // pixel is C itself, for every C and every bank (n = 1, 2, 3, 4, 5, 8, 11, 500).
  Vunit dut;
  reset(dut);
  const uint32_t ns[] = {1, 2, 3, 4, 5, 8, 11, 500};
  const uint32_t cs[] = {1, 0x7fff, 0x8000, 0xffff, 0x1234};
  for (uint32_t n : ns)
    for (uint32_t c : cs) {
      Line ln;
      ln.n = n;
      ln.c = c;
      ln.len = 2;
      write_and_start(dut, ln);
      const Trace t = run_line(dut, static_cast<int>(ln.len) + kLineOverhead);
      INFO("n = " << n << ", C = " << c);
      REQUIRE(t.pixels.size() == 3);
      for (uint32_t p : t.pixels) CHECK(p == c);
    }
}

TEST_CASE("specular_unit zero conditions", "[rtl][unit]") {
  Vunit dut;
  reset(dut);
  SECTION("invalid n gives l+1 zero pixels") {
    const uint32_t n = GENERATE(0u, 1001u, 1023u);
    Line ln;
    ln.n = n;
    ln.len = 4;
    write_and_start(dut, ln);
    const Trace t = run_line(dut, kLatency + 8);
    REQUIRE(t.pixels.size() == 5);
    for (uint32_t p : t.pixels) CHECK(p == 0);
  }
  SECTION("angles at and past the lobe edge give 0; psi crossing 0 gives the peak") {
    // n = 1 (k = 1, a close to 1): pixels at -3, -1.5, 0, 1.5, 3 rad (each + 2^-28 i:
    // the code of +-1.5 rad is not a multiple of 2^-20 rad, so the one's complement of the
    // negative one truncates to the same |psi|_t and the two pixels must be equal).
    Line ln;
    ln.n = 1;
    ln.c = 0x7fff;
    ln.psi0 = -3 * (1 << 28) - 2;
    ln.dpsi = 3 * (1 << 27) + 1;
    ln.len = 4;
    write_and_start(dut, ln);
    const Trace t = run_line(dut, kLatency + 8);
    REQUIRE(t.pixels.size() == 5);
    CHECK(t.pixels[0] == 0);
    CHECK(t.pixels[4] == 0);
    CHECK(t.pixels[2] == peak_intensity(ln.c));
    CHECK(t.pixels[1] == t.pixels[3]);  // cos is even
    CHECK(t.pixels[1] > 0);
  }
}

TEST_CASE("specular_unit pixels follow C cos^k(a psi) in pixel order", "[rtl][unit]") {
  // Independent check of the whole datapath: a from the ROM 9 word (a = word / 2^18 * pi/2),
  // cos^k in long double, 0 where |psi| >= pi/2 or a|psi| >= pi/2. The device differs from
  // C cos^k(a|psi|) by (x = a|psi|, h = pi/2 / 256 the ROM 12 entry spacing):
  //   - the angle it uses: |psi| one's complement (2^-28 low) and truncated to 2^-20 rad,
  //     zeta truncated to 2^-20 quarter turns (8 address + 12 weight bits), so x is reduced
  //     by at most dx = a (2^-20 + 2^-28) + pi/2 * 2^-20, which moves cos^k by at most
  //     S_k dx, S_k = max |(cos^k)'| = sqrt(k) ((k-1)/k)^((k-1)/2) (1 for k = 1);
  //   - the linear interpolation between entries: h^2/8 max |(cos^k)''| = h^2/8 * k
  //     ((cos^k)'' = k cos^(k-2) x ((k-1) sin^2 x - cos^2 x), largest in size at x = 0);
  //   - the table rounding (1/2 LSB of 2^-18) and the weight rounding (1/2 LSB): 2^-18;
  //   - C times all of that, then the output rounding, 1/2 LSB of 2^-15.
  // For k = 16 this is about 3 output LSB; the old direct table's bound was a full step of
  // pi/2 / 4096 times the slope, and half a ROM 12 step would be S_k h / 2, more
  // than fifty times this.
  const specular::device::Format f;
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::minimax;
  const auto coef = specular::coef_rom_image(f, spec);
  const uint32_t n = GENERATE(1u, 2u, 3u, 4u, 5u, 8u, 11u, 100u, 1000u);
  const int k = k_of(n);
  constexpr long double pi = std::numbers::pi_v<long double>;
  const long double a = coef[n] / 262144.0L * pi / 2;
  Vunit dut;
  reset(dut);
  Line ln;
  ln.n = n;
  ln.c = 0x6000;  // 0.75
  ln.len = 400;
  // Sweep a*psi from -pi/2*1.1 to +pi/2*1.1 over the line (|psi| also passes pi/2 where
  // a < 1: those pixels are 0 by the pi/2 test).
  const long double span = 1.1L * pi / 2 / a;
  ln.psi0 = static_cast<int32_t>(std::llround(-span * (1 << 28)));
  ln.dpsi = static_cast<int32_t>(std::llround(2 * span / ln.len * (1 << 28)));
  write_and_start(dut, ln);
  const Trace t = run_line(dut, static_cast<int>(ln.len) + kLatency + 6);
  REQUIRE(t.pixels.size() == ln.len + 1);
  const long double h = pi / 2 / 256;
  const long double slope = std::sqrt(static_cast<long double>(k)) *
                            std::pow(static_cast<long double>(k - 1) / k, (k - 1) / 2.0L);
  const long double dx = a * (std::ldexp(1.0L, -20) + std::ldexp(1.0L, -28)) + pi / 2 * std::ldexp(1.0L, -20);
  const long double cos_err = slope * dx + h * h / 8 * k + std::ldexp(1.0L, -18);
  const long double cv = ln.c / 32768.0L;
  const long double tol = cv * cos_err + std::ldexp(1.0L, -16);
  CHECK(tol < 4.0L / 32768.0L);  // a few output LSB at most, for every k
  long double worst = 0;
  int nonzero = 0;
  for (uint32_t i = 0; i <= ln.len; ++i) {
    const long double psi = (static_cast<long double>(ln.psi0) + i * static_cast<long double>(ln.dpsi)) /
                            (1 << 28);
    const long double x = a * std::fabs(psi);
    const bool zero = std::fabs(psi) >= pi / 2 || x >= pi / 2;
    const long double ideal = zero ? 0.0L : cv * std::pow(std::cos(x), k);
    const long double err = std::fabs(t.pixels[i] / 32768.0L - ideal);
    worst = std::max(worst, err);
    nonzero += t.pixels[i] != 0;
    INFO("n = " << n << " (k = " << k << "), pixel " << i << ", psi = " << static_cast<double>(psi)
                << ", a*psi = " << static_cast<double>(x) << ", rtl " << t.pixels[i] << ", ideal "
                << static_cast<double>(ideal * 32768) << " LSB, bound " << static_cast<double>(tol * 32768));
    CHECK(err <= tol);
  }
  CHECK(nonzero > 20);
  UNSCOPED_INFO("n = " << n << ": worst |rtl - C cos^k(a psi)| = " << static_cast<double>(worst * 32768)
                       << " LSB, bound " << static_cast<double>(tol * 32768) << " LSB");
}

TEST_CASE("specular_unit agrees with the golden model on random lines", "[rtl][unit]") {
  const specular::device::Format f;
  const auto model = specular::load_device_model(f, specular::kCoefMinimaxHex, specular::kCosHex);
  Vunit dut;
  reset(dut);
  std::mt19937 rng(2026);
  std::uniform_int_distribution<uint32_t> c_any(0, 0xffff), n_any(0, 1023), len_any(0, 60);
  std::uniform_int_distribution<int32_t> psi_any(-(3 << 28), 3 << 28), dpsi_any(-(1 << 24), 1 << 24);
  for (int line = 0; line < 40; ++line) {
    Line ln{c_any(rng), psi_any(rng), dpsi_any(rng), line % 4 == 0 ? n_any(rng) : 1 + n_any(rng) % 30, len_any(rng)};
    write_and_start(dut, ln);
    const Trace t = run_line(dut, static_cast<int>(ln.len) + kLineOverhead);
    specular::device::Registers r;
    r.c = ln.c;
    r.psi0 = ln.psi0;
    r.dpsi = ln.dpsi;
    r.n = ln.n;
    r.len = ln.len;
    const auto want = model.line(r);
    INFO("line " << line << ": n = " << ln.n << ", l = " << ln.len);
    REQUIRE(t.pixels == want);
    CHECK(t.first_valid == kLatency);
    CHECK(t.nonzero_while_invalid == 0);
  }
}

TEST_CASE("specular_unit asynchronous reset aborts a line", "[rtl][unit]") {
  Vunit dut;
  reset(dut);
  Line ln;
  ln.len = 20;
  write_and_start(dut, ln);
  run_line(dut, kLatency + 3);  // mid-line: busy, pixels flowing
  dut.eval();
  REQUIRE(dut.busy_o == 1);
  REQUIRE(dut.valid_o == 1);
  dut.rst_ni = 0;
  dut.eval();  // no clock edge: the reset acts at once
  CHECK(dut.busy_o == 0);
  CHECK(dut.valid_o == 0);
  CHECK(dut.intensity_o == 0);
  tick(dut);
  dut.rst_ni = 1;
  dut.eval();
  // Registers are 0 after reset: n = 0 is invalid, so a plain start gives one zero pixel.
  dut.start_i = 1;
  const Trace t = run_line(dut, kLatency + 4);
  REQUIRE(t.pixels.size() == 1);
  CHECK(t.pixels[0] == 0);
}
