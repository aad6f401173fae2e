// SPDX-License-Identifier: Apache-2.0
// The pipelined multiplier (specular_pipe_mul), multiplier 11 (|psi| -> ROM 12 address,
// weight and zero flag, both builds) and multiplier 13 (C * cos^k, output register).
// Expected values come from the real-number meaning of the formats in long double
// (radians, quarter turns, fractions of 1), not from the RTL's shifts: every quantity here
// has at most 64 significant bits, so long double holds it exactly. Every block is driven
// with one new operand set per clock and checked its latency later (pipe_stream.hpp), and
// again with random stalls (en_i low, garbage on the inputs).
#include "Vangle_mul.h"
#include "Vangle_mul_patent.h"
#include "Vintensity_mul.h"
#include "Vpipe_mul_12x12.h"
#include "Vpipe_mul_12x12_t16.h"
#include "Vpipe_mul_12x12_t18.h"
#include "Vpipe_mul_16x19.h"
#include "Vpipe_mul_16x19_t16.h"
#include "Vpipe_mul_16x19_t18.h"
#include "Vpipe_mul_21x21.h"
#include "Vpipe_mul_21x21_t16.h"
#include "Vpipe_mul_21x21_t18.h"
#include "Vpipe_mul_3x2.h"
#include "Vpipe_mul_4x8.h"
#include "Vpipe_mul_5x3.h"
#include "Vpipe_mul_6x6.h"
#include "Vpipe_mul_7x5.h"
#include "Vpipe_mul_6x9_t5.h"
#include "Vpipeline_single.h"
#include "Vpipeline_single_specular_pipeline.h"
#include "Vpipeline_patent.h"
#include "Vpipeline_patent_specular_pipeline.h"
#include "phong_mul_widths.inc"
#include "pipe_stream.hpp"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using specular::rtl_test::reset;
using specular::rtl_test::run_stream;
using specular::rtl_test::tick;

namespace {

auto always_on = [](long) { return true; };
auto accept_any = [](auto&) { return std::string(); };

// en_i low in about a third of the cycles, in runs of 1..6 cycles.
struct RandomStalls {
  std::mt19937 rng{4242};
  int left = 0;
  bool operator()(long) {
    if (left > 0) {
      --left;
      return false;
    }
    if (rng() % 3 == 0) {
      left = static_cast<int>(rng() % 6);
      return false;
    }
    return true;
  }
};

// ------------------------------------------------------------------------------------
// specular_pipe_mul: p = a * b exactly through the radix-4 tree every instance uses; the
// latency it must show is specular_pkg::pipe_mul_stages(BBits) (via sim/specular_pipeline.sv)
// ------------------------------------------------------------------------------------

struct MulItem {
  uint64_t a, b;
};

template <class Dut>
int run_pipe_mul(Dut& dut, int latency, int a_bits, int b_bits, const std::vector<MulItem>& items, bool stalls) {
  std::mt19937_64 junk(7);
  const uint64_t a_mask = (uint64_t{1} << a_bits) - 1, b_mask = (uint64_t{1} << b_bits) - 1;
  RandomStalls st;
  // a3_i = 3 a, as every caller computes it a clock ahead (phong_mul computes its own).
  auto set_a = [](Dut& m, uint64_t a) {
    m.a_i = a;
    if constexpr (requires { m.a3_i; }) m.a3_i = 3 * a;
  };
  auto apply = [&](Dut& m, const MulItem& it) {
    set_a(m, it.a);
    m.b_i = it.b;
  };
  auto garbage = [&](Dut& m) {
    set_a(m, junk() & a_mask);
    m.b_i = junk() & b_mask;
  };
  auto check = [](Dut& m, const MulItem& it) {
    const uint64_t want = it.a * it.b;  // < 2^(a_bits + b_bits) <= 2^42
    if (static_cast<uint64_t>(m.p_o) == want) return std::string();
    std::ostringstream s;
    s << it.a << " * " << it.b << ": rtl " << static_cast<uint64_t>(m.p_o) << ", want " << want;
    return s.str();
  };
  if (stalls) return run_stream(dut, latency, items, apply, garbage, check, accept_any, st);
  return run_stream(dut, latency, items, apply, garbage, check, accept_any, always_on);
}

std::vector<MulItem> mul_items(int a_bits, int b_bits, int random_count, uint64_t seed) {
  const uint64_t a_max = (uint64_t{1} << a_bits) - 1, b_max = (uint64_t{1} << b_bits) - 1;
  std::vector<MulItem> v{{a_max, b_max}, {0, b_max}, {a_max, 0}, {0, 0}, {1, 1}, {a_max, 1}, {1, b_max}};
  // Single bits against single bits and against all ones: every partial product row alone.
  for (int i = 0; i < a_bits; ++i) {
    for (int j = 0; j < b_bits; ++j) v.push_back({uint64_t{1} << i, uint64_t{1} << j});
    v.push_back({uint64_t{1} << i, b_max});
  }
  for (int j = 0; j < b_bits; ++j) v.push_back({a_max, uint64_t{1} << j});
  // Every radix-4 digit value (0, 1, 2, 3) in every digit position, against all ones.
  for (int j = 0; j < b_bits; j += 2)
    for (uint64_t d = 1; d < 4; ++d) v.push_back({a_max, (d << j) & b_max});
  std::mt19937_64 rng(seed);
  for (int i = 0; i < random_count; ++i) v.push_back({rng() & a_max, rng() & b_max});
  return v;
}

std::vector<MulItem> every_pair(int a_bits, int b_bits) {
  std::vector<MulItem> all;
  for (uint64_t a = 0; a < (uint64_t{1} << a_bits); ++a)
    for (uint64_t b = 0; b < (uint64_t{1} << b_bits); ++b) all.push_back({a, b});
  return all;
}

// specular_pkg::pipe_mul_stages(b), from sim/specular_pipeline.sv's table.
int tree_stages(int b) {
  using P = Vpipeline_single_specular_pipeline;
  const int bit = 8 * b;
  return static_cast<int>((P::TreeStagesTable[bit / 32] >> (bit % 32)) & 0xffu);
}

}  // namespace

TEST_CASE("pipe_mul 21x21 (multiplier 11's tree): exact products, one pair per clock", "[rtl][pipe_mul]") {
  Vpipe_mul_21x21 dut;
  dut.clk_i = 0;
  dut.eval();
  const int latency = tree_stages(21);
  CHECK(run_pipe_mul(dut, latency, 21, 21, mul_items(21, 21, 20000, 11), false) == 0);
}

TEST_CASE("pipe_mul 21x21 holds every stage while en_i is low", "[rtl][pipe_mul][stall]") {
  Vpipe_mul_21x21 dut;
  dut.clk_i = 0;
  dut.eval();
  const int latency = tree_stages(21);
  CHECK(run_pipe_mul(dut, latency, 21, 21, mul_items(21, 21, 5000, 12), true) == 0);
}

// Small widths, every operand pair: odd and even row counts, a single row (BBits = 2), two
// rows (BBits = 3) and a tree of three levels (BBits = 8).
template <class Dut>
void every_pair_case(int a_bits, int b_bits) {
  Dut dut;
  dut.clk_i = 0;
  dut.eval();
  const int latency = tree_stages(b_bits);
  const auto all = every_pair(a_bits, b_bits);
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, all, false) == 0);
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, all, true) == 0);
}

TEST_CASE("pipe_mul at small widths: every operand pair, with and without stalls", "[rtl][pipe_mul]") {
  SECTION("7x5") { every_pair_case<Vpipe_mul_7x5>(7, 5); }
  SECTION("6x6") { every_pair_case<Vpipe_mul_6x6>(6, 6); }
  SECTION("4x8") { every_pair_case<Vpipe_mul_4x8>(4, 8); }
  SECTION("5x3") { every_pair_case<Vpipe_mul_5x3>(5, 3); }
  SECTION("3x2") { every_pair_case<Vpipe_mul_3x2>(3, 2); }
}

// Both styles (TileBits 0: LUT tree; 16, 18: DSP tiles; docs/pipeline.md#multiplier-styles)
// at the widths of multipliers 11, 12 and 13: exact products with the same latency,
// pipe_mul_stages(BBits), with and without stalls.
template <class Dut>
void style_case(int a_bits, int b_bits, uint64_t seed) {
  Dut dut;
  dut.clk_i = 0;
  dut.eval();
  const int latency = tree_stages(b_bits);
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, mul_items(a_bits, b_bits, 5000, seed), false) == 0);
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, mul_items(a_bits, b_bits, 2000, seed + 1), true) == 0);
}

TEST_CASE("pipe_mul styles: LUT tree and DSP tiles give the same products at the same latency",
          "[rtl][pipe_mul][style]") {
  SECTION("21x21 tiles 16") { style_case<Vpipe_mul_21x21_t16>(21, 21, 21); }
  SECTION("21x21 tiles 18") { style_case<Vpipe_mul_21x21_t18>(21, 21, 22); }
  SECTION("12x12 tree") { style_case<Vpipe_mul_12x12>(12, 12, 23); }
  SECTION("12x12 tiles 16") { style_case<Vpipe_mul_12x12_t16>(12, 12, 24); }
  SECTION("12x12 tiles 18") { style_case<Vpipe_mul_12x12_t18>(12, 12, 25); }
  SECTION("16x19 tree") { style_case<Vpipe_mul_16x19>(16, 19, 26); }
  SECTION("16x19 tiles 16") { style_case<Vpipe_mul_16x19_t16>(16, 19, 27); }
  SECTION("16x19 tiles 18") { style_case<Vpipe_mul_16x19_t18>(16, 19, 28); }
  SECTION("6x9 tiles 5 (2 x 2, padded), every pair") { every_pair_case<Vpipe_mul_6x9_t5>(6, 9); }
}

// phong_mul (rtl/competitors/phong) in both DSP styles at two widths of phong_stream's default
// configuration (tests/rtl/CMakeLists.txt lists them and says why two suffice); its latency is
// its own public Stages, phong_pkg::mul_stages, one operand register more than the tree's.
template <class Dut, class Module>
void phong_style_case(int a_bits, int b_bits, uint64_t seed) {
  Dut dut;
  dut.clk_i = 0;
  dut.eval();
  const int latency = Module::Stages;  // phong_pkg::mul_stages(BBits)
  CHECK(latency > tree_stages(b_bits));
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, mul_items(a_bits, b_bits, 3000, seed), false) == 0);
  CHECK(run_pipe_mul(dut, latency, a_bits, b_bits, mul_items(a_bits, b_bits, 1000, seed + 1), true) == 0);
}

#define PHONG_MUL_SECTION(a, b, t) \
  SECTION(#a "x" #b " tiles " #t) { phong_style_case<Vphong_mul_##a##x##b##_t##t, Vphong_mul_##a##x##b##_t##t##_phong_mul>(a, b, a * 1000 + b * 10 + t); }

TEST_CASE("phong_mul styles: DSP tiles give exact products at phong_mul's latency",
          "[rtl][pipe_mul][style][phong]") {
  SPECULAR_PHONG_MUL_WIDTHS(PHONG_MUL_SECTION)
}

// ------------------------------------------------------------------------------------
// Multiplier 11
// ------------------------------------------------------------------------------------
namespace {

constexpr long double kPi = std::numbers::pi_v<long double>;
constexpr int kAccBits = 44;
constexpr uint64_t kAccMask = (uint64_t{1} << kAccBits) - 1;
// Latencies: the configurations' stage counts (sim/specular_pipeline.sv).
constexpr int kMul11Latency = static_cast<int>(Vpipeline_single_specular_pipeline::Mul11Stages);
constexpr int kMul11PatentLatency = static_cast<int>(Vpipeline_patent_specular_pipeline::Mul11Stages);
constexpr int64_t kHalfPiCode = 421657429;             // ceil(pi/2 * 2^28)

struct AngleItem {
  int64_t psi;    // register 8 code, 28 fraction bits (radians)
  uint32_t coef;  // ROM 9 word
  bool n_valid;
};

struct AngleExpect {
  bool zero;
  unsigned addr, frac;
};

// Interpolated build (CosInterp = 1, CoefFrac = 18): the address is the 8 bits of zeta
// below the binary point, the weight the next 12. Direct (patent) build (CoefFrac = 15):
// the address is zeta * 4096 rounded half up, the weight 0.
AngleExpect expect_angle(const AngleItem& it, bool patent) {
  const long double lsb = std::ldexp(1.0L, -28);
  const long double abs_true = std::fabs(static_cast<long double>(it.psi)) * lsb;
  // One's complement magnitude: one code below |psi| for negative psi.
  const long double mag = it.psi >= 0 ? abs_true : abs_true - lsb;
  const bool far = abs_true >= kPi / 2;
  const long double psi_t = std::floor(std::ldexp(mag, 20)) / std::ldexp(1.0L, 20);
  AngleExpect e{};
  if (!patent) {
    const long double zeta = it.coef / std::ldexp(1.0L, 18) * psi_t;  // quarter turns
    const long double pos = zeta * 256;
    const long double a = std::floor(pos);
    e.zero = far || zeta >= 1 || !it.n_valid;
    e.addr = static_cast<unsigned>(a);
    e.frac = static_cast<unsigned>(std::floor((pos - a) * 4096));
  } else {
    const long double zeta = it.coef / std::ldexp(1.0L, 15) * psi_t;
    const long double a = std::floor(zeta * 4096 + 0.5L);
    e.zero = far || a >= 4096 || !it.n_valid;
    e.addr = static_cast<unsigned>(std::fmod(a, 4096.0L));
    e.frac = 0;
  }
  return e;
}

template <class Dut>
std::string check_angle(Dut& m, const AngleItem& it, bool patent) {
  const AngleExpect e = expect_angle(it, patent);
  const bool zero = m.zero_o;
  const unsigned addr = m.addr_o, frac = m.frac_o;
  bool ok = zero == e.zero;
  if (ok && !e.zero) ok = addr == e.addr && frac == e.frac;
  if (ok && patent) ok = frac == 0;
  if (ok) return {};
  std::ostringstream s;
  s << "psi " << it.psi << " coef " << it.coef << " n_valid " << it.n_valid << ": rtl zero " << zero << " addr "
    << addr << " frac " << frac << ", want zero " << e.zero << " addr " << e.addr << " frac " << e.frac;
  return s.str();
}

template <class Dut>
int run_angle(Dut& dut, const std::vector<AngleItem>& items, bool patent, bool stalls) {
  std::mt19937_64 junk(99);
  const uint32_t coef_mask = patent ? (1u << 18) - 1 : (1u << 21) - 1;
  auto apply = [](Dut& m, const AngleItem& it) {
    m.psi_i = static_cast<uint64_t>(it.psi) & kAccMask;
    m.coef_i = it.coef;
    m.n_valid_i = it.n_valid;
  };
  auto garbage = [&](Dut& m) {
    m.psi_i = junk() & kAccMask;
    m.coef_i = static_cast<uint32_t>(junk()) & coef_mask;
    m.n_valid_i = junk() & 1;
  };
  auto check = [patent](Dut& m, const AngleItem& it) { return check_angle(m, it, patent); };
  const int latency = patent ? kMul11PatentLatency : kMul11Latency;
  if (stalls) return run_stream(dut, latency, items, apply, garbage, check, accept_any, RandomStalls{});
  return run_stream(dut, latency, items, apply, garbage, check, accept_any, always_on);
}

std::vector<AngleItem> random_angles(int count, bool patent, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const uint32_t coef_max = patent ? (1u << 18) - 1 : (1u << 21) - 1;
  // Typical coefficients a*2/pi in [1/8, 8) quarter turns per radian.
  const uint32_t one = patent ? 1u << 15 : 1u << 18;
  std::uniform_int_distribution<uint32_t> coef_any(0, coef_max), coef_typ(one / 8, coef_max);
  std::uniform_int_distribution<int64_t> psi_lobe(-(int64_t{1} << 29), int64_t{1} << 29);  // |psi| < 2 rad
  std::uniform_int_distribution<int64_t> psi_edge(-64, 64);
  std::vector<AngleItem> v;
  for (int i = 0; i < count; ++i) {
    AngleItem it{};
    switch (i % 4) {
      case 0:  // anywhere in register 8
        it.psi = static_cast<int64_t>(rng() << 20) >> 20;
        it.coef = coef_any(rng);
        break;
      case 1:  // near the pi/2 test, either sign
        it.psi = (i % 8 == 1 ? 1 : -1) * (kHalfPiCode + psi_edge(rng));
        it.coef = coef_typ(rng) / 4;
        break;
      default:  // inside the lobe: mostly nonzero
        it.psi = psi_lobe(rng) >> (rng() % 6);
        it.coef = coef_typ(rng) >> (rng() % 4);
        break;
    }
    it.n_valid = rng() % 37 != 0;
    v.push_back(it);
  }
  return v;
}

}  // namespace

TEST_CASE("multiplier 11: pi/2 test, quarter-turn crossing, n_valid, hand-computed addresses", "[rtl][mul11]") {
  // Hand-written expectations (not only the long double formula): quarter turns per radian
  // 1 (coef 2^18) makes zeta = psi_t; coef 2^17 keeps zeta < 0.8 up to |psi| = pi/2.
  struct Case {
    AngleItem in;
    bool zero;
    unsigned addr, frac;  // checked when not zero
  };
  const uint32_t unit = 1u << 18, half = 1u << 17;
  const int64_t one_rad = int64_t{1} << 28;
  const Case cases[] = {
      // ceil(pi/2 * 2^28) = 421657429 is at or past pi/2, 421657428 below, both signs
      // (the negative code's one's complement is 421657428 / 421657427).
      {{kHalfPiCode, half, true}, true, 0, 0},
      {{-kHalfPiCode, half, true}, true, 0, 0},
      {{kHalfPiCode - 1, half, true}, false, 201, 253},
      {{-(kHalfPiCode - 1), half, true}, false, 201, 253},
      {{kHalfPiCode + 1000, 1, true}, true, 0, 0},  // far even with a tiny coefficient
      {{int64_t{1} << 40, 1, true}, true, 0, 0},     // far beyond pi/2
      {{-(int64_t{1} << 42), 1, true}, true, 0, 0},
      // zeta crossing one quarter turn: psi = 1 rad gives zeta = 1 (zero); 1 rad - 2^-28
      // truncates to 1 - 2^-20 (address 255, weight 4095); -1 rad has the one's complement
      // magnitude 1 - 2^-28, so it is not zero either; -(1 rad + 2^-28) is.
      {{one_rad, unit, true}, true, 0, 0},
      {{one_rad - 1, unit, true}, false, 255, 4095},
      {{-one_rad, unit, true}, false, 255, 4095},
      {{-(one_rad + 1), unit, true}, true, 0, 0},
      // zeta = (129 * 4096 + 5) / 2^20: address 129, weight 5 (bits below 2^-20 truncated).
      {{(int64_t{129 * 4096 + 5} << 8) + 255, unit, true}, false, 129, 5},
      {{0, unit, true}, false, 0, 0},  // the peak
      {{0, unit, false}, true, 0, 0},  // invalid n
      {{one_rad / 2, unit, false}, true, 0, 0},
      {{one_rad / 2, unit, true}, false, 128, 0},
      {{12345678, 0, true}, false, 0, 0},  // coefficient 0 (unused n): address 0
      // Largest coefficient, 8 - 2^-18 quarter turns per radian: 1/8 rad gives zeta =
      // 1 - 2^-21 (address 255, weight 4095); 1/8 rad + 2^-20 is past the quarter turn.
      {{one_rad >> 3, (1u << 21) - 1, true}, false, 255, 4095},
      {{(one_rad >> 3) + (1 << 8), (1u << 21) - 1, true}, true, 0, 0},
  };
  std::vector<AngleItem> items;
  for (const auto& c : cases) items.push_back(c.in);
  // The long double formula against the hand values first (so a wrong formula is caught too).
  for (const auto& c : cases) {
    const AngleExpect e = expect_angle(c.in, false);
    INFO("psi " << c.in.psi << " coef " << c.in.coef);
    CHECK(e.zero == c.zero);
    if (!c.zero) {
      CHECK(e.addr == c.addr);
      CHECK(e.frac == c.frac);
    }
  }
  Vangle_mul dut;
  reset(dut);
  CHECK(run_angle(dut, items, false, false) == 0);
}

TEST_CASE("multiplier 11: random operands streamed one per clock", "[rtl][mul11]") {
  const auto items = random_angles(40000, false, 71489);
  int nonzero = 0, far_edge = 0;
  for (const auto& it : items) {
    const AngleExpect e = expect_angle(it, false);
    nonzero += !e.zero;
    far_edge += (it.psi == kHalfPiCode || it.psi == -kHalfPiCode) ? 1 : 0;
  }
  CHECK(nonzero > 10000);  // the sample exercises the address path, not only the zeros
  CHECK(far_edge > 20);
  Vangle_mul dut;
  reset(dut);
  CHECK(run_angle(dut, items, false, false) == 0);
}

TEST_CASE("multiplier 11 holds every stage while en_i is low (stall)", "[rtl][mul11][stall]") {
  Vangle_mul dut;
  reset(dut);
  CHECK(run_angle(dut, random_angles(10000, false, 5), false, true) == 0);
}

TEST_CASE("multiplier 11, patent build: rounded 12-bit address, zero at 4096", "[rtl][mul11][patent]") {
  // Hand values: coef 2^15 = one quarter turn per radian, psi_t = psi.
  struct Case {
    AngleItem in;
    bool zero;
    unsigned addr;
  };
  const uint32_t unit = 1u << 15;
  const Case cases[] = {
      {{int64_t{2047 * 256 + 128} << 8, unit, true}, false, 2048},  // 2047.5 rounds up
      {{int64_t{2047 * 256 + 127} << 8, unit, true}, false, 2047},
      {{int64_t{4095 * 256 + 128} << 8, unit, true}, true, 0},      // rounds to 4096: zero
      {{int64_t{4095 * 256 + 127} << 8, unit, true}, false, 4095},
      {{-(int64_t{4095 * 256 + 127} << 8), unit, true}, false, 4095},
      {{kHalfPiCode, 1u << 13, true}, true, 0},
      {{-kHalfPiCode, 1u << 13, true}, true, 0},
      {{kHalfPiCode - 1, 1u << 13, true}, false, 1608},  // pi/2 / 4 quarter turns: 0.3927 * 4096
      {{-(kHalfPiCode - 1), 1u << 13, true}, false, 1608},
      {{0, unit, true}, false, 0},
      {{0, unit, false}, true, 0},
  };
  std::vector<AngleItem> items;
  for (const auto& c : cases) {
    items.push_back(c.in);
    const AngleExpect e = expect_angle(c.in, true);
    INFO("psi " << c.in.psi);
    CHECK(e.zero == c.zero);
    if (!c.zero) CHECK(e.addr == c.addr);
  }
  const auto rnd = random_angles(20000, true, 16);
  items.insert(items.end(), rnd.begin(), rnd.end());
  Vangle_mul_patent dut;
  reset(dut);
  CHECK(run_angle(dut, items, true, false) == 0);
  CHECK(run_angle(dut, random_angles(5000, true, 17), true, true) == 0);
}

// ------------------------------------------------------------------------------------
// Multiplier 13
// ------------------------------------------------------------------------------------
namespace {

// 6: radix-4 tree over the 19 bits of cos^k (a row register + 4 adder levels), output.
constexpr int kMul13Latency = static_cast<int>(Vpipeline_single_specular_pipeline::Mul13Stages);
constexpr uint32_t kCosOne = 1u << 18;             // cos^k = 1.0

struct IntensityItem {
  uint32_t c, cosk;
  bool zero;
};

// C (15 fraction bits) times cos^k (18 fraction bits), rounded half up to 15 bits.
uint32_t expect_intensity(const IntensityItem& it) {
  if (it.zero) return 0;
  const long double real = (it.c / 32768.0L) * (it.cosk / 262144.0L);
  return static_cast<uint32_t>(std::floor(real * 32768.0L + 0.5L));
}

std::string check_intensity(Vintensity_mul& m, const IntensityItem& it) {
  const uint32_t want = expect_intensity(it);
  if (m.intensity_o == want) return {};
  std::ostringstream s;
  s << "C " << it.c << " cosk " << it.cosk << " zero " << it.zero << ": rtl " << m.intensity_o << ", want "
    << want;
  return s.str();
}

auto intensity_zero = [](Vintensity_mul& m) {
  return m.intensity_o == 0 ? std::string() : "output " + std::to_string(m.intensity_o) + " before any pixel";
};

int run_intensity(Vintensity_mul& dut, const std::vector<IntensityItem>& items, bool stalls) {
  std::mt19937 junk(3);
  auto apply = [](Vintensity_mul& m, const IntensityItem& it) {
    m.c_i = it.c;
    m.c3_i = 3 * it.c;  // the stream computes 3C once per span
    m.cosk_i = it.cosk;
    m.zero_i = it.zero;
  };
  auto garbage = [&](Vintensity_mul& m) {
    m.c_i = junk() & 0xffff;
    m.c3_i = 3 * m.c_i;
    m.cosk_i = junk() % (kCosOne + 1);
    m.zero_i = junk() & 1;
  };
  if (stalls) return run_stream(dut, kMul13Latency, items, apply, garbage, check_intensity, intensity_zero, RandomStalls{});
  return run_stream(dut, kMul13Latency, items, apply, garbage, check_intensity, intensity_zero, always_on);
}

std::vector<IntensityItem> random_intensities(int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<IntensityItem> v;
  for (int i = 0; i < count; ++i) v.push_back({static_cast<uint32_t>(rng() & 0xffff), static_cast<uint32_t>(rng() % (kCosOne + 1)), rng() % 50 == 0});
  return v;
}

}  // namespace

TEST_CASE("multiplier 13: C x 1 = C exactly for every C, rounding, extremes", "[rtl][mul13]") {
  std::vector<IntensityItem> items;
  for (uint32_t c = 0; c <= 0xffff; ++c) items.push_back({c, kCosOne, false});
  const std::vector<IntensityItem> hand = {
      {0xffff, kCosOne, false},      // largest product: C, no overflow
      {0xffff, kCosOne - 1, false},  // 0xffff * (1 - 2^-18) = 0xffff - 0.25: rounds to 0xffff
      {0x8000, kCosOne / 2, false},  // 1 * 1/2
      {1, kCosOne / 2, false},       // exactly half an LSB: rounds up to 1
      {1, kCosOne / 2 - 1, false},   // just under half: 0
      {3, kCosOne / 2, false},       // 1.5 LSB: 2
      {0, kCosOne, false},
      {0xffff, 0, false},
      {0xffff, kCosOne, true},  // the zero flag wins
  };
  const uint32_t hand_want[] = {0xffff, 0xffff, 0x4000, 1, 0, 2, 0, 0, 0};
  for (size_t i = 0; i < hand.size(); ++i) CHECK(expect_intensity(hand[i]) == hand_want[i]);
  items.insert(items.end(), hand.begin(), hand.end());
  Vintensity_mul dut;
  dut.en_i = 1;
  reset(dut);
  dut.eval();
  CHECK(dut.intensity_o == 0);  // reset state: 0 before any pixel
  CHECK(run_intensity(dut, items, false) == 0);
}

TEST_CASE("multiplier 13: random operands streamed one per clock", "[rtl][mul13]") {
  Vintensity_mul dut;
  reset(dut);
  CHECK(run_intensity(dut, random_intensities(30000, 29), false) == 0);
}

TEST_CASE("multiplier 13 holds every stage while en_i is low (stall)", "[rtl][mul13][stall]") {
  Vintensity_mul dut;
  reset(dut);
  CHECK(run_intensity(dut, random_intensities(10000, 30), true) == 0);
}

TEST_CASE("multiplier 13: reset in flight zeroes the output until new pixels arrive", "[rtl][mul13]") {
  Vintensity_mul dut;
  reset(dut);
  // Fill the tree with large products, then reset asynchronously: the tree has no reset,
  // the keep flags do, so the output reads 0 at once and for the next Latency - 1 clocks.
  std::vector<IntensityItem> big(20, {0xffff, kCosOne, false});
  CHECK(run_intensity(dut, big, false) == 0);
  dut.en_i = 1;
  dut.c_i = 0xffff;
  dut.c3_i = 3 * 0xffff;
  dut.cosk_i = kCosOne;
  dut.zero_i = 0;
  for (int i = 0; i < kMul13Latency; ++i) tick(dut);
  dut.eval();
  REQUIRE(dut.intensity_o == 0xffff);
  dut.rst_ni = 0;
  dut.eval();
  CHECK(dut.intensity_o == 0);
  tick(dut);
  dut.rst_ni = 1;
  dut.eval();
  CHECK(run_intensity(dut, random_intensities(100, 31), false) == 0);
}
