// SPDX-License-Identifier: Apache-2.0
// Down counter 5: the borrow (35) comes with the (l+1)-th count pulse, exactly once; the
// count then stays 0 until l is written again (rtl/core/specular_down_counter.sv; the stream
// writes l with every accepted span).
#include "Vcounter.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

void load(Vcounter& dut, unsigned len) {
  dut.len_we_i = 1;
  dut.len_i = len;
  dut.count_i = 0;
  tick(dut);
  dut.len_we_i = 0;
  dut.eval();
}

// Gives pulses until the borrow appears (at most `limit`), returns how many were given
// (the one carrying the borrow included), or -1 if none came.
long pulses_to_borrow(Vcounter& dut, long limit) {
  for (long p = 1; p <= limit; ++p) {
    dut.count_i = 1;
    dut.eval();
    const bool borrow = dut.borrow_o;
    tick(dut);
    if (borrow) {
      dut.count_i = 0;
      dut.eval();
      return p;
    }
  }
  dut.count_i = 0;
  dut.eval();
  return -1;
}

}  // namespace

TEST_CASE("counter 5 borrows on the (l+1)-th pulse", "[rtl][counter]") {
  const unsigned len = GENERATE(0u, 1u, 2u, 3u, 4u, 17u, 1000u, 2047u);
  Vcounter dut;
  reset(dut);
  load(dut, len);
  CHECK(static_cast<unsigned>(dut.count_o) == len);
  CHECK(pulses_to_borrow(dut, 5000) == static_cast<long>(len) + 1);
  // After the borrow the count stays 0 (no wrap): a further pulse borrows at once.
  CHECK(dut.count_o == 0);
  CHECK(dut.zero_o == 1);
  for (int i = 0; i < 3; ++i) tick(dut);
  CHECK(dut.count_o == 0);
  CHECK(pulses_to_borrow(dut, 5000) == 1);
  CHECK(dut.count_o == 0);
  // The next line is written again, as the stream does with every span.
  load(dut, len);
  CHECK(static_cast<unsigned>(dut.count_o) == len);
  CHECK(pulses_to_borrow(dut, 5000) == static_cast<long>(len) + 1);
}

TEST_CASE("counter 5: a write in the borrow's cycle starts the next line", "[rtl][counter]") {
  // The stream accepts the next span at the edge where the previous span's last pixel
  // takes the borrow: the write wins over the count pulse.
  const unsigned len = GENERATE(0u, 1u, 5u);
  Vcounter dut;
  reset(dut);
  load(dut, 2);
  CHECK(pulses_to_borrow(dut, 2) == -1);   // pulses 1 and 2: no borrow yet
  dut.count_i = 1;
  dut.len_we_i = 1;
  dut.len_i = len;
  dut.eval();
  CHECK(dut.borrow_o == 1);
  tick(dut);
  dut.count_i = 0;
  dut.len_we_i = 0;
  dut.eval();
  CHECK(static_cast<unsigned>(dut.count_o) == len);
  CHECK(dut.zero_o == (len == 0 ? 1 : 0));
  CHECK(pulses_to_borrow(dut, 5000) == static_cast<long>(len) + 1);
}

TEST_CASE("counter 5 holds without pulses and borrows only on a pulse", "[rtl][counter]") {
  Vcounter dut;
  reset(dut);
  CHECK(dut.count_o == 0);
  dut.count_i = 0;
  dut.eval();
  CHECK(dut.borrow_o == 0);  // count 0 but no pulse: no borrow
  load(dut, 3);
  for (int i = 0; i < 10; ++i) tick(dut);
  CHECK(dut.count_o == 3);
  dut.count_i = 1;
  dut.eval();
  CHECK(dut.borrow_o == 0);
  tick(dut);
  dut.eval();
  CHECK(dut.count_o == 2);
}
