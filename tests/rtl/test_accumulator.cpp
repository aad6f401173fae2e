// Accumulator (adder 6, mux 7, register 8): psi0 on the first strobe, psi + dpsi after,
// sign extension from 32 to 44 bits, no overflow over the longest line.
#include "Vaccumulator.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr int kAccBits = 44;

int64_t sext44(uint64_t raw) {
  const uint64_t m = uint64_t{1} << (kAccBits - 1);
  raw &= (uint64_t{1} << kAccBits) - 1;
  return static_cast<int64_t>(raw ^ m) - static_cast<int64_t>(m);
}

// Runs a line of `pixels` strobes and checks register 8 after each one against the
// arithmetic sum psi0 + i * dpsi (exact in int64).
void run_line(Vaccumulator& dut, int32_t psi0, int32_t dpsi, int pixels) {
  dut.psi0_i = static_cast<uint32_t>(psi0);
  dut.dpsi_i = static_cast<uint32_t>(dpsi);
  for (int i = 0; i < pixels; ++i) {
    dut.we_i = 1;
    dut.sel_i = (i == 0) ? 0 : 1;
    tick(dut);
    const int64_t expect = static_cast<int64_t>(psi0) + static_cast<int64_t>(i) * dpsi;
    const int64_t got = sext44(dut.psi_o);
    if (got != expect) {
      INFO("psi0 = " << psi0 << ", dpsi = " << dpsi << ", pixel " << i);
      REQUIRE(got == expect);
    }
  }
  dut.we_i = 0;
}

}  // namespace

TEST_CASE("accumulator loads psi0 then adds dpsi", "[rtl][accumulator]") {
  Vaccumulator dut;
  reset(dut);
  CHECK(dut.psi_o == 0);
  run_line(dut, 0x10000000, 0x00123456, 10);            // positive
  run_line(dut, -0x20000000, 0x01000000, 100);          // crosses zero
  run_line(dut, 0x7fffffff, -0x00000001, 5);            // from the top of the range
}

TEST_CASE("accumulator holds without a strobe", "[rtl][accumulator]") {
  Vaccumulator dut;
  reset(dut);
  run_line(dut, 12345, 678, 3);
  const auto before = dut.psi_o;
  dut.sel_i = 1;
  for (int i = 0; i < 5; ++i) tick(dut);
  CHECK(dut.psi_o == before);
}

TEST_CASE("accumulator does not overflow over 2048 extreme steps", "[rtl][accumulator]") {
  Vaccumulator dut;
  reset(dut);
  const int32_t lo = INT32_MIN, hi = INT32_MAX;
  run_line(dut, lo, lo, 2048);
  run_line(dut, hi, hi, 2048);
}

TEST_CASE("accumulator random lines", "[rtl][accumulator]") {
  Vaccumulator dut;
  reset(dut);
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<int32_t> any(INT32_MIN, INT32_MAX);
  std::uniform_int_distribution<int> len(1, 300);
  for (int line = 0; line < 50; ++line) run_line(dut, any(rng), any(rng), len(rng));
}
