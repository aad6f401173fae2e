// Top level specular_unit: the protocol of SPEC section 6 as fixed for the RTL
// (latency 6, one pixel per clock, busy through the last pixel, l + 7 clocks per line),
// zero conditions, writes and starts while busy, asynchronous reset, and the RTL
// parameter defaults against specular::device::Format.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter header
#include "Vunit.h"
#include "Vunit_specular_unit.h"
#pragma GCC diagnostic pop
#include "rtl_harness.hpp"

#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr int kLatency = 6;        // start in cycle s -> first valid pixel in s + 6
constexpr int kLineOverhead = 7;   // start to next accepted start: l + 7 cycles

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

// C * cos^0 with the saturated ROM word 0xffff, rounded: floor(C * 65535/65536 + 1/2).
uint32_t peak_intensity(uint32_t c) {
  return static_cast<uint32_t>(std::floor(c * (65535.0L / 65536.0L) + 0.5L));
}

}  // namespace

TEST_CASE("specular_unit parameter defaults equal device::Format", "[rtl][unit]") {
  const specular::device::Format f;
  using R = Vunit_specular_unit;  // public parameters (/*verilator public*/)
  CHECK(R::CBits == f.c_bits);
  CHECK(R::CFrac == f.c_frac);
  CHECK(R::AngleBits == f.angle_bits);
  CHECK(R::AngleFrac == f.angle_frac);
  CHECK(R::AccBits == f.acc_bits);
  CHECK(R::NBits == f.n_bits);
  CHECK(R::LenBits == f.len_bits);
  CHECK(R::CoefBits == f.coef_bits);
  CHECK(R::CoefFrac == f.coef_frac);
  CHECK(R::PsiMulFrac == f.psi_mul_frac);
  CHECK(R::CosAddrBits == f.cos_addr_bits);
  CHECK(R::CosDataBits == f.cos_data_bits);
  CHECK(R::NumBanks == static_cast<int>(f.banks.size()));
  uint64_t packed = 0;
  for (size_t j = 0; j < f.bank_max_n.size(); ++j)
    packed |= static_cast<uint64_t>(f.bank_max_n[j]) << (j * f.n_bits);
  CHECK(static_cast<uint64_t>(R::BankMaxN) == packed);
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
  const Trace t = run_line(dut, static_cast<int>(l) + 12);
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

TEST_CASE("specular_unit zero conditions", "[rtl][unit]") {
  Vunit dut;
  reset(dut);
  SECTION("invalid n gives l+1 zero pixels") {
    const uint32_t n = GENERATE(0u, 1001u, 1023u);
    Line ln;
    ln.n = n;
    ln.len = 4;
    write_and_start(dut, ln);
    const Trace t = run_line(dut, 14);
    REQUIRE(t.pixels.size() == 5);
    for (uint32_t p : t.pixels) CHECK(p == 0);
  }
  SECTION("angles at and past the lobe edge give 0; psi crossing 0 gives the peak") {
    // n = 1 (k = 1, a close to 1): pixels at -3, -1.5, 0, 1.5, 3 rad.
    Line ln;
    ln.n = 1;
    ln.c = 0x7fff;
    ln.psi0 = -3 * (1 << 28);
    ln.dpsi = 3 * (1 << 27);
    ln.len = 4;
    write_and_start(dut, ln);
    const Trace t = run_line(dut, 14);
    REQUIRE(t.pixels.size() == 5);
    CHECK(t.pixels[0] == 0);
    CHECK(t.pixels[4] == 0);
    CHECK(t.pixels[2] == peak_intensity(ln.c));
    CHECK(t.pixels[1] == t.pixels[3]);  // cos is even
    CHECK(t.pixels[1] > 0);
  }
}

TEST_CASE("specular_unit pixels follow C cos^k(a psi) in pixel order", "[rtl][unit]") {
  // Independent check of the whole datapath: a from the ROM 9 word, cos^k in long double;
  // the device differs by the ROM 12 address step (pi/2 / 4096 in a*psi), the ROM word
  // rounding and the output rounding.
  const specular::device::Format f;
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::minimax;
  const auto coef = specular::coef_rom_image(f, spec);
  const uint32_t n = GENERATE(1u, 2u, 5u, 7u, 100u, 1000u);
  const int k = n == 1 ? 1 : n == 2 ? 2 : n <= 6 ? 4 : 16;
  const long double a = coef[n] / 32768.0L * std::numbers::pi_v<long double> / 2;
  Vunit dut;
  reset(dut);
  Line ln;
  ln.n = n;
  ln.c = 0x6000;  // 0.75
  ln.len = 200;
  // Sweep a*psi from -pi/2*1.1 to +pi/2*1.1 over the line.
  const long double span = 1.1L * std::numbers::pi_v<long double> / 2 / a;
  ln.psi0 = static_cast<int32_t>(std::llround(-span * (1 << 28)));
  ln.dpsi = static_cast<int32_t>(std::llround(2 * span / ln.len * (1 << 28)));
  write_and_start(dut, ln);
  const Trace t = run_line(dut, static_cast<int>(ln.len) + 12);
  REQUIRE(t.pixels.size() == ln.len + 1);
  const long double step = std::numbers::pi_v<long double> / 2 / 4096;
  const long double slope = k == 1 ? 1.0L : std::sqrt(static_cast<long double>(k));
  const long double tol = (ln.c / 32768.0L) * slope * step + 2.0L / 32768.0L;
  for (uint32_t i = 0; i <= ln.len; ++i) {
    const long double psi = (static_cast<long double>(ln.psi0) + i * (long double)ln.dpsi) /
                            (1 << 28);
    const long double x = a * std::fabs(psi);
    const long double ideal =
        x >= std::numbers::pi_v<long double> / 2 ? 0.0L : (ln.c / 32768.0L) * std::pow(std::cos(x), k);
    INFO("n = " << n << ", pixel " << i << ", a*psi = " << (double)x);
    CHECK(std::fabs(t.pixels[i] / 32768.0L - ideal) <= tol);
  }
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
  run_line(dut, 8);  // mid-line: busy, pixels flowing
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
  const Trace t = run_line(dut, 10);
  REQUIRE(t.pixels.size() == 1);
  CHECK(t.pixels[0] == 0);
}
