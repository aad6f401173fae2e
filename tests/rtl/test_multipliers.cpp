// Multiplier 11 (|psi| -> ROM 12 address and zero flag) and multiplier 13 (C * cos^k).
// Expected values are computed in long double from the real-number meaning of the
// formats (radians, quarter turns), not with the RTL's shifts: every product here is
// below 2^64 so long double holds it exactly.
#include "Vangle_mul.h"
#include "Vintensity_mul.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr long double kAngleScale = 268435456.0L;  // 2^28: radians of register 8
constexpr long double kCoefScale = 32768.0L;        // 2^15: ROM 9 word per unit of a*2/pi
constexpr long double kPsiMulScale = 1048576.0L;    // 2^20: |psi| kept at multiplier 11
constexpr long double kCosAddrSteps = 4096.0L;      // 2^12 ROM 12 entries per quarter turn

struct AddrExpect {
  unsigned addr;
  bool zero;
};

AddrExpect expect_addr(int64_t psi_raw, uint32_t coef, bool n_valid) {
  const long double abs_rad = std::fabs(static_cast<long double>(psi_raw)) / kAngleScale;
  const bool far = abs_rad >= 8.0L;
  // |psi| truncated to a multiple of 2^-20 rad.
  const long double psi_t = std::floor(abs_rad * kPsiMulScale) / kPsiMulScale;
  const long double zeta_quarter_turns = (coef / kCoefScale) * psi_t;
  const long double addr = std::floor(zeta_quarter_turns * kCosAddrSteps + 0.5L);
  const bool past = addr >= kCosAddrSteps;
  return {static_cast<unsigned>(std::fmod(addr, kCosAddrSteps)), far || past || !n_valid};
}

void check_angle(Vangle_mul& dut, int64_t psi_raw, uint32_t coef, bool n_valid) {
  dut.psi_i = static_cast<uint64_t>(psi_raw) & ((uint64_t{1} << 44) - 1);
  dut.coef_i = coef;
  dut.n_valid_i = n_valid;
  tick(dut);  // stage 1: |psi|_t, far, coefficient
  tick(dut);  // stage 2: zeta, rounded address, zero flag
  const AddrExpect e = expect_addr(psi_raw, coef, n_valid);
  INFO("psi_raw = " << psi_raw << ", coef = " << coef << ", n_valid = " << n_valid);
  REQUIRE(static_cast<bool>(dut.zero_o) == e.zero);
  if (!e.zero) REQUIRE(static_cast<unsigned>(dut.addr_o) == e.addr);
}

}  // namespace

TEST_CASE("multiplier 11: boundaries of the zero conditions", "[rtl][mul11]") {
  Vangle_mul dut;
  dut.en_i = 1;
  reset(dut);
  const uint32_t unit = 1u << 15;  // a * 2/pi = 1: zeta (quarter turns) = |psi| in rad
  const int64_t eight_rad = int64_t{8} << 28;
  check_angle(dut, eight_rad, 1u << 12, true);          // |psi| = 8 rad: far
  check_angle(dut, -eight_rad, 1u << 12, true);
  check_angle(dut, eight_rad - 1, 1u << 12, true);      // just under 8 rad
  check_angle(dut, -(eight_rad - 1), 1u << 12, true);
  check_angle(dut, int64_t{40} << 28, 1u << 12, true);  // far beyond
  // zeta * 4096 = psi_t / 256 with the unit coefficient: 4095.5 rounds up to 4096 (zero),
  // one step below stays at 4095.
  check_angle(dut, int64_t{1048448} << 8, unit, true);
  check_angle(dut, int64_t{1048447} << 8, unit, true);
  check_angle(dut, -(int64_t{1048447} << 8), unit, true);
  check_angle(dut, (int64_t{1048448} << 8) - 1, unit, true);  // truncation drops the -1
  check_angle(dut, 0, unit, true);                            // peak: address 0
  check_angle(dut, 0, unit, false);                           // invalid n: zero
  check_angle(dut, 12345678, 0, true);                        // coef 0 (unused n)
  check_angle(dut, 12345678, (1u << 18) - 1, true);           // largest coefficient
}

TEST_CASE("multiplier 11: random angles and coefficients", "[rtl][mul11]") {
  Vangle_mul dut;
  dut.en_i = 1;
  reset(dut);
  std::mt19937_64 rng(71489);
  std::uniform_int_distribution<int64_t> psi_any(-(int64_t{9} << 28), int64_t{9} << 28);
  std::uniform_int_distribution<int64_t> psi_small(-(int64_t{1} << 26), int64_t{1} << 26);
  std::uniform_int_distribution<uint32_t> coef_any(0, (1u << 18) - 1);
  std::uniform_int_distribution<uint32_t> coef_typ(1u << 12, 1u << 17);
  int nonzero = 0;
  for (int i = 0; i < 20000; ++i) {
    const bool small = (i % 2) == 0;
    const int64_t psi = small ? psi_small(rng) : psi_any(rng);
    const uint32_t coef = small ? coef_typ(rng) : coef_any(rng);
    check_angle(dut, psi, coef, (i % 97) != 0);
    nonzero += dut.zero_o ? 0 : 1;
  }
  CHECK(nonzero > 2000);  // the sample exercises the address path, not just the zeros
}

namespace {

void check_intensity(Vintensity_mul& dut, uint32_t c, uint32_t cosk, bool zero) {
  dut.c_i = c;
  dut.cosk_i = cosk;
  dut.zero_i = zero;
  tick(dut);
  // C (15 fraction bits) times cos^k (16 fraction bits), rounded half up to 15 bits.
  const long double real = (c / 32768.0L) * (cosk / 65536.0L);
  const auto expect = zero ? 0u : static_cast<uint32_t>(std::floor(real * 32768.0L + 0.5L));
  INFO("C = " << c << ", cosk = " << cosk << ", zero = " << zero);
  REQUIRE(static_cast<uint32_t>(dut.intensity_o) == expect);
}

}  // namespace

TEST_CASE("multiplier 13: rounding and extremes", "[rtl][mul13]") {
  Vintensity_mul dut;
  dut.en_i = 1;
  reset(dut);
  check_intensity(dut, 0xffff, 0xffff, false);  // largest product: 0xfffe, no overflow
  check_intensity(dut, 0x8000, 0xffff, false);  // C = 1, cos^k(0) saturated: 0x8000
  check_intensity(dut, 0x4000, 0xffff, false);
  check_intensity(dut, 1, 0x8000, false);       // exactly half an LSB: rounds up to 1
  check_intensity(dut, 1, 0x7fff, false);       // just under half: 0
  check_intensity(dut, 0, 0xffff, false);
  check_intensity(dut, 0xffff, 0xffff, true);   // zero flag wins
}

TEST_CASE("multiplier 13: random operands", "[rtl][mul13]") {
  Vintensity_mul dut;
  dut.en_i = 1;
  reset(dut);
  std::mt19937 rng(29);
  std::uniform_int_distribution<uint32_t> w16(0, 0xffff);
  for (int i = 0; i < 20000; ++i) check_intensity(dut, w16(rng), w16(rng), (i % 50) == 0);
}

TEST_CASE("multiplier 13 and ROM 12 hold their outputs while en_i is low (stall)", "[rtl][mul13][stall]") {
  Vintensity_mul mul;
  mul.en_i = 1;
  reset(mul);
  check_intensity(mul, 0x8000, 0x4000, false);  // 0x2000
  mul.en_i = 0;
  mul.c_i = 0xffff;
  mul.cosk_i = 0xffff;
  for (int i = 0; i < 3; ++i) {
    tick(mul);
    CHECK(mul.intensity_o == 0x2000);
  }
  mul.en_i = 1;
  tick(mul);
  CHECK(mul.intensity_o == 0xfffe);
}

TEST_CASE("multiplier 11 holds its stages while en_i is low (stall)", "[rtl][mul11][stall]") {
  Vangle_mul dut;
  dut.en_i = 1;
  reset(dut);
  dut.n_valid_i = 1;
  dut.coef_i = 1u << 15;           // a * 2/pi = 1: zeta = |psi| in quarter turns
  dut.psi_i = int64_t{1} << 27;    // 0.5 rad
  tick(dut);
  tick(dut);
  const auto addr = dut.addr_o;
  const auto zero = dut.zero_o;
  CHECK(addr == (1u << 11));       // 0.5 quarter turns * 4096
  dut.en_i = 0;
  dut.psi_i = int64_t{3} << 26;    // 0.75 rad: must not reach the output while stalled
  for (int i = 0; i < 3; ++i) {
    tick(dut);
    CHECK(dut.addr_o == addr);
    CHECK(dut.zero_o == zero);
  }
  dut.en_i = 1;
  tick(dut);
  tick(dut);
  CHECK(dut.addr_o == 3u << 10);
}
