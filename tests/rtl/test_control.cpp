// SPDX-License-Identifier: Apache-2.0
// Control unit 14 of the streaming pipeline, cycle by cycle (its block model has the
// block's default PipeDepth, kLatency below). Counter 5 is modelled here (loaded with l on accept, decremented
// by every count pulse 34), so the unit is checked against the stream contract,
// independently of its implementation. adv_i is the pipeline advance (in the core a
// register of the output buffer); a pixel leaves the last stage at an edge where
// out_valid_o and adv_i are both high.
//   * with adv_i high and spans always offered, a span accepted in cycle t has pixel i in
//     the last stage in cycle t + PipeDepth + i; the next span is accepted in cycle t + l + 1
//     (one pixel per clock, l = 0 included);
//   * mux select 36 is 0 exactly on accepting strobes, a strobe (37) and a count pulse
//     (34) per pixel leaving register 8;
//   * under any adv_i pattern: nothing moves while adv_i is low, exactly l + 1 pixels per
//     span with out_last_o on the last, in order, and span_ready_o = adv_i && register 8
//     free, never depending on span_valid_i.
#include "Vcontrol.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <deque>
#include <random>
#include <string>
#include <vector>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr int kLatency = 5;  // accept cycle -> first pixel on the output

struct Bench {
  Vcontrol dut;
  int counter = 0;
  Bench() {
    dut.span_valid_i = 0;
    dut.adv_i = 0;
    dut.cnt_zero_i = 1;
    reset(dut);
  }
  // Drives one cycle; returns {accepted, transferred, last of the transferred pixel}.
  struct Result {
    bool accepted, fired, last, valid;
  };
  Result cycle(bool offer, int len, bool ready) {
    dut.span_valid_i = offer;
    dut.adv_i = ready;
    dut.cnt_zero_i = counter == 0;
    dut.eval();
    // span_ready_o must not depend on span_valid_i.
    const bool ready_with = dut.span_ready_o;
    dut.span_valid_i = !offer;
    dut.eval();
    CHECK(static_cast<bool>(dut.span_ready_o) == ready_with);
    dut.span_valid_i = offer;
    dut.eval();
    const bool adv = ready;
    const bool reg8_free = !(dut.stage_valid_o & 1) || counter == 0;
    CHECK(static_cast<bool>(dut.span_ready_o) == (adv && reg8_free));
    const Result r{offer && dut.span_ready_o, dut.out_valid_o && ready, static_cast<bool>(dut.out_last_o),
                   static_cast<bool>(dut.out_valid_o)};
    CHECK(static_cast<bool>(dut.accept_o) == r.accepted);
    if (r.accepted) CHECK(dut.sel_o == 0);
    if (dut.strobe_o && !r.accepted) CHECK(dut.sel_o == 1);
    CHECK(static_cast<bool>(dut.count_o) == (adv && (dut.stage_valid_o & 1)));
    if (r.accepted) counter = len;
    else if (dut.count_o && counter > 0) --counter;
    tick(dut);
    return r;
  }
};

}  // namespace

TEST_CASE("control unit: back-to-back spans, ready high, one pixel per clock", "[rtl][control]") {
  const int l = GENERATE(0, 1, 2, 3);
  Bench b;
  std::vector<int> accept_cycles, valid_cycles, last_cycles;
  for (int c = 0; c < 40; ++c) {
    const auto r = b.cycle(true, l, true);
    if (r.accepted) accept_cycles.push_back(c);
    if (r.fired) valid_cycles.push_back(c);
    if (r.fired && r.last) last_cycles.push_back(c);
  }
  REQUIRE(accept_cycles.size() >= 3);
  for (size_t j = 0; j < accept_cycles.size(); ++j) CHECK(accept_cycles[j] == static_cast<int>(j) * (l + 1));
  // From the first pixel on, a pixel every cycle.
  REQUIRE(!valid_cycles.empty());
  CHECK(valid_cycles.front() == kLatency);
  for (size_t j = 0; j < valid_cycles.size(); ++j) CHECK(valid_cycles[j] == kLatency + static_cast<int>(j));
  for (size_t j = 0; j < last_cycles.size(); ++j) CHECK(last_cycles[j] == kLatency + static_cast<int>(j + 1) * (l + 1) - 1);
}

TEST_CASE("control unit: random offers and adv_i, count / last / order", "[rtl][control]") {
  const uint64_t seed = GENERATE(1, 2, 3, 4);
  std::mt19937_64 rng(seed);
  Bench b;
  std::deque<bool> owed;  // last flags of the pixels owed, in order
  bool prev_stalled = false, prev_last = false;
  int spans = 0, pixels = 0, len = static_cast<int>(rng() % 4);
  bool offering = false;
  const double p_ready = 0.2 + 0.2 * static_cast<double>(seed);
  std::bernoulli_distribution ready_d(std::min(p_ready, 1.0)), offer_d(0.6);
  for (int c = 0; c < 3000; ++c) {
    if (!offering) offering = offer_d(rng);
    const bool ready = ready_d(rng);
    b.dut.eval();
    if (prev_stalled) {
      CHECK(b.dut.out_valid_o == 1);
      CHECK(static_cast<bool>(b.dut.out_last_o) == prev_last);
    }
    const auto r = b.cycle(offering, len, ready);
    if (r.fired) {
      REQUIRE(!owed.empty());
      CHECK(r.last == owed.front());
      owed.pop_front();
      ++pixels;
    }
    if (r.accepted) {
      for (int i = 0; i <= len; ++i) owed.push_back(i == len);
      ++spans;
      offering = false;
      len = (rng() % 8 == 0) ? static_cast<int>(rng() % 40) : static_cast<int>(rng() % 4);
    }
    prev_stalled = r.valid && !ready;
    prev_last = r.last;
  }
  // Drain.
  for (int c = 0; c < 200 && !owed.empty(); ++c) {
    const auto r = b.cycle(false, 0, true);
    if (r.fired) {
      CHECK(r.last == owed.front());
      owed.pop_front();
      ++pixels;
    }
  }
  CHECK(owed.empty());
  CHECK(spans > 100);
  b.dut.eval();
  CHECK(b.dut.busy_o == 0);
  CHECK(b.dut.out_valid_o == 0);
}

TEST_CASE("control unit: reset drops everything in flight", "[rtl][control]") {
  Bench b;
  for (int c = 0; c < 3; ++c) b.cycle(true, 3, true);
  b.dut.eval();
  CHECK(b.dut.busy_o == 1);
  reset(b.dut);
  b.counter = 0;
  for (int c = 0; c < 8; ++c) {
    const auto r = b.cycle(false, 0, true);
    CHECK_FALSE(r.fired);
    CHECK(b.dut.busy_o == 0);
  }
}
