// SPDX-License-Identifier: Apache-2.0
// Output buffer of the stream (rtl/prim/specular_out_buf.sv, default Width = 33), checked cycle
// by cycle against an independent queue model of its header's contract:
//   * two entries; adv_o is high exactly when the buffer holds at most one pixel (so a
//     pixel pushed at the next edge always has room), and it is a register; adv_d_o is the
//     value adv_o takes at the next edge;
//   * a push is in_valid_i at an edge where adv_o is high (in_* are ignored otherwise); a
//     pop is px_valid_o && px_ready_i (AXI4-Stream transfer);
//   * pixels leave in push order, none lost or duplicated, one clock after their push;
//   * px_valid_o and px_data_o hold while px_valid_o && !px_ready_i; px_data_o reads 0 while
//     px_valid_o is low; with px_ready_i always high, one pixel per clock and adv_o stays high;
//   * the asynchronous reset empties the buffer at once (adv_o high, px_valid_o low).
// Every pushed pixel carries a serial number in its low bits (random high bits), so loss,
// duplication and reordering show up whatever the model says.
#include "Vout_buf.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <deque>
#include <random>
#include <string>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr int kWidth = 33;                       // specular_out_buf's default Width
constexpr uint64_t kMask = (uint64_t{1} << kWidth) - 1;
constexpr int kSerialBits = 24;                  // low bits of a pixel: its push serial
constexpr uint64_t kSerialMask = (uint64_t{1} << kSerialBits) - 1;
constexpr size_t kCapacity = 2;                  // entries, specified

struct Bench {
  Vout_buf dut;
  std::deque<uint64_t> model;  // pixels in the buffer, head first
  bool model_adv = true;       // the registered room
  uint64_t next_push = 0;      // serial of the next pixel pushed
  uint64_t next_pop = 0;       // serial the next transfer must carry
  bool prev_stalled = false;   // last cycle: px_valid_o && !px_ready_i
  uint64_t prev_data = 0;
  long cycles = 0, pushes = 0, pops = 0, stalls = 0, full_cycles = 0;
  std::string error;           // first mismatch, empty while none

  Bench() {
    dut.in_valid_i = 0;
    dut.in_data_i = 0;
    dut.px_ready_i = 0;
    reset(dut);
  }

  void fail(const std::string& what) {
    if (error.empty()) error = "cycle " + std::to_string(cycles) + ": " + what;
  }

  // The asynchronous reset, asserted in the middle of a cycle: the outputs clear without
  // a clock edge, every pixel in the buffer is dropped.
  void async_reset() {
    dut.rst_ni = 0;
    dut.eval();
    if (dut.px_valid_o) fail("px_valid_o high during reset");
    if (dut.px_data_o != 0) fail("px_data_o not 0 during reset");
    if (!dut.adv_o) fail("adv_o low during reset");
    tick(dut);
    dut.rst_ni = 1;
    dut.eval();
    model.clear();
    model_adv = true;
    next_pop = next_push;  // the pixels in the buffer are gone
    prev_stalled = false;
  }

  // One cycle: drive the inputs, check the outputs, apply the edge. in_valid / ready as
  // given; the data of an offered pixel is its would-be serial with random high bits.
  // Returns whether a pixel was pushed.
  bool cycle(bool in_valid, bool ready, uint64_t high_bits) {
    const uint64_t data = ((high_bits << kSerialBits) | (next_push & kSerialMask)) & kMask;
    dut.in_valid_i = in_valid;
    dut.in_data_i = data;
    dut.px_ready_i = ready;
    dut.eval();
    const bool adv = dut.adv_o;
    const bool valid = dut.px_valid_o;
    const uint64_t out = dut.px_data_o;

    // Outputs against the model.
    if (adv != model_adv) fail("adv_o = " + std::to_string(adv) + ", model " + std::to_string(model_adv));
    if (valid != !model.empty()) fail("px_valid_o = " + std::to_string(valid) + " with " +
                                      std::to_string(model.size()) + " pixels in the model");
    if (valid && !model.empty() && out != model.front()) fail("px_data_o is not the oldest pixel");
    if (!valid && out != 0) fail("px_data_o not 0 while px_valid_o is low");
    // AXI4-Stream: after a stall, still valid with the same data (independent of the model).
    if (prev_stalled && !valid) fail("px_valid_o dropped without a transfer");
    if (prev_stalled && out != prev_data) fail("px_data_o changed while stalled");
    // Registered outputs: they must not depend on this cycle's inputs.
    dut.in_valid_i = !in_valid;
    dut.in_data_i = ~data & kMask;
    dut.px_ready_i = !ready;
    dut.eval();
    if (dut.adv_o != adv || dut.px_valid_o != valid || dut.px_data_o != out)
      fail("an output depends combinationally on the inputs");
    dut.in_valid_i = in_valid;
    dut.in_data_i = data;
    dut.px_ready_i = ready;
    dut.eval();

    // The edge: the model's push and pop, the serial checks.
    const bool push = model_adv && in_valid;
    const bool pop = !model.empty() && ready;
    if (pop) {
      if ((out & kSerialMask) != (next_pop & kSerialMask))
        fail("transfer of serial " + std::to_string(out & kSerialMask) + ", expected " +
             std::to_string(next_pop & kSerialMask) + " (lost, duplicated or reordered)");
      model.pop_front();
      ++next_pop;
      ++pops;
    }
    if (push) {
      model.push_back(data);
      ++next_push;
      ++pushes;
    }
    if (model.size() > kCapacity) fail("the model overflowed (adv_o let a pixel into a full buffer)");
    if (model.size() == kCapacity) ++full_cycles;
    model_adv = model.size() <= 1;
    // adv_d_o announces adv_o of the next clock (the inputs of this one are still applied).
    if (dut.adv_d_o != model_adv)
      fail("adv_d_o = " + std::to_string(dut.adv_d_o) + ", the model's next adv_o " + std::to_string(model_adv));
    prev_stalled = valid && !ready;
    if (prev_stalled) ++stalls;
    prev_data = out;
    tick(dut);
    ++cycles;
    return push;
  }
};

}  // namespace

TEST_CASE("out_buf: reset state and asynchronous reset", "[rtl][out_buf]") {
  Bench b;
  b.dut.eval();
  CHECK(b.dut.adv_o == 1);
  CHECK(b.dut.px_valid_o == 0);
  CHECK(b.dut.px_data_o == 0);
  // Fill it (ready low), then reset without a clock edge: empty at once.
  for (int i = 0; i < 4; ++i) b.cycle(true, false, 0x1ff);
  b.dut.eval();
  CHECK(b.dut.px_valid_o == 1);
  CHECK(b.dut.adv_o == 0);
  b.async_reset();
  CHECK(b.error.empty());
  b.dut.eval();
  CHECK(b.dut.adv_o == 1);
  CHECK(b.dut.px_valid_o == 0);
  CHECK(b.dut.px_data_o == 0);
  // Usable again: the next pixel is the first out.
  for (int i = 0; i < 6; ++i) b.cycle(i == 0, true, 7);
  INFO(b.error);
  CHECK(b.error.empty());
  CHECK(b.pushes == 3);  // two before the reset, one after
  CHECK(b.pops == 1);
}

TEST_CASE("out_buf: capacity is two pixels", "[rtl][out_buf]") {
  Bench b;
  // px_ready_i low, a pixel offered every cycle: exactly two enter, then adv_o stays low
  // and the head is held.
  long entered = 0;
  for (int i = 0; i < 50; ++i) entered += b.cycle(true, false, static_cast<uint64_t>(i)) ? 1 : 0;
  INFO(b.error);
  CHECK(b.error.empty());
  CHECK(entered == 2);
  b.dut.eval();
  CHECK(b.dut.adv_o == 0);
  CHECK(b.dut.px_valid_o == 1);
  CHECK((b.dut.px_data_o & kSerialMask) == 0);
  // One transfer: the next cycle has room again (adv_o is registered), and one more enters.
  b.cycle(false, true, 0);
  b.dut.eval();
  CHECK(b.dut.adv_o == 1);
  CHECK((b.dut.px_data_o & kSerialMask) == 1);
  CHECK(b.cycle(true, false, 0));
  CHECK_FALSE(b.cycle(true, false, 0));
  // Drain: serials 1 and 2, in order.
  for (int i = 0; i < 4; ++i) b.cycle(false, true, 0);
  CHECK(b.error.empty());
  CHECK(b.pops == 3);
  CHECK(b.pushes == 3);
}

TEST_CASE("out_buf: ready always high, one pixel per clock, one clock of latency", "[rtl][out_buf]") {
  Bench b;
  std::mt19937_64 rng(11);
  for (int c = 0; c < 2000; ++c) {
    b.dut.eval();
    CHECK(b.dut.adv_o == 1);                                  // never stalls the pipeline
    CHECK(b.dut.px_valid_o == (c > 0 ? 1 : 0));               // pushed at c-1, out at c
    if (c > 0) CHECK((b.dut.px_data_o & kSerialMask) == static_cast<uint64_t>(c - 1));
    b.cycle(true, true, rng());
    CHECK(b.model.size() <= 1);
  }
  INFO(b.error);
  CHECK(b.error.empty());
  CHECK(b.pushes == 2000);
  CHECK(b.pops == 1999);
}

TEST_CASE("out_buf: random push / pop / ready against the queue model", "[rtl][out_buf]") {
  const uint64_t seed = GENERATE(1, 2, 3, 4, 5);
  std::mt19937_64 rng(seed);
  Bench b;
  // Phases of random length with their own probabilities of in_valid and px_ready_i
  // (always, never, often, rarely, half), and now and then an asynchronous reset.
  const int probs[] = {0, 10, 50, 90, 100};
  constexpr long kCycles = 60000;
  while (b.cycles < kCycles && b.error.empty()) {
    const int p_valid = probs[rng() % 5];
    const int p_ready = probs[rng() % 5];
    const long len = 1 + static_cast<long>(rng() % 200);
    for (long i = 0; i < len && b.error.empty(); ++i) {
      const bool in_valid = static_cast<int>(rng() % 100) < p_valid;
      const bool ready = static_cast<int>(rng() % 100) < p_ready;
      b.cycle(in_valid, ready, rng());
    }
    if (rng() % 40 == 0) b.async_reset();
  }
  // Drain: everything pushed since the last reset comes out.
  for (int i = 0; i < 4; ++i) b.cycle(false, true, 0);
  INFO("seed " << seed << ": " << b.error);
  REQUIRE(b.error.empty());
  CHECK(b.model.empty());
  CHECK(b.next_pop == b.next_push);
  // The run reached every state: pushes and pops by the thousand, a full buffer, stalls.
  CHECK(b.pushes > 10000);
  CHECK(b.pops > 10000);
  CHECK(b.full_cycles > 1000);
  CHECK(b.stalls > 1000);
}
