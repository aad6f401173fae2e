// SPDX-License-Identifier: Apache-2.0
// Accumulator (adder 6, mux 7, register 8): psi0 on the first strobe, psi + dpsi after,
// sign extension from 32 to 44 bits, no overflow over the longest line. Register 8 is two
// stages (low half, then high half with the carry): the pixel written by a strobe appears on
// psi_o after the next step_i, which the stream gives whenever stage A's pixel moves on.
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

// Runs a line of `pixels` strobes, one per clock as the stream does (each strobe after the
// first also steps the previous pixel into stage B; `stall_every` > 0 inserts a clock with
// neither every so many pixels), then one step to flush, and checks psi_o after every step
// against the arithmetic sum psi0 + i * dpsi (exact in int64).
void run_line(Vaccumulator& dut, int32_t psi0, int32_t dpsi, int pixels, int stall_every = 0) {
  dut.psi0_i = static_cast<uint32_t>(psi0);
  dut.dpsi_i = static_cast<uint32_t>(dpsi);
  auto check = [&](int i) {
    const int64_t expect = static_cast<int64_t>(psi0) + static_cast<int64_t>(i) * dpsi;
    const int64_t got = sext44(dut.psi_o);
    if (got != expect) {
      INFO("psi0 = " << psi0 << ", dpsi = " << dpsi << ", pixel " << i);
      REQUIRE(got == expect);
    }
  };
  for (int i = 0; i <= pixels; ++i) {
    if (stall_every > 0 && i > 0 && i % stall_every == 0) {
      const auto held = dut.psi_o;
      dut.we_i = 0;
      dut.step_i = 0;
      tick(dut);
      REQUIRE(dut.psi_o == held);
    }
    dut.we_i = i < pixels;
    dut.sel_i = (i == 0) ? 0 : 1;
    dut.step_i = i > 0;
    tick(dut);
    if (i > 0) check(i - 1);
  }
  dut.we_i = 0;
  dut.step_i = 0;
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
  // Stalls inside a line (neither strobe nor step) change nothing.
  run_line(dut, -987654, 4321, 40, 3);
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
  for (int line = 0; line < 50; ++line) run_line(dut, any(rng), any(rng), len(rng), line % 3 ? 0 : 1 + line % 7);
}
