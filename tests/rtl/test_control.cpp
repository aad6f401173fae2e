// Control unit 14, cycle by cycle, for l = 0..3 against the patent's timing (SPEC 5)
// as fixed for the synchronous RTL: with start_i high in cycle s while idle,
//   strobes (register 8 write 37) and count pulses (34) in s+1 .. s+1+l,
//   mux select (36) 0 on the first strobe and 1 on the others,
//   data valid (29) in s+6 .. s+6+l (PipeDepth = 5 behind the strobe: register 8, two
//   stages of multiplier 11, ROM 12, multiplier 13 / output register),
//   busy (28) in s+1 .. s+6+l, a new start accepted from s+7+l on,
// the borrow coming from a counter modelled here: loaded with l, decremented by every
// count pulse, borrow on the pulse that passes zero. Starts while busy are ignored.
#include "Vcontrol.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

constexpr int kValidFrom = 6;  // first valid cycle after the start cycle

struct Signals {
  bool strobe, sel, count, valid, valid_next, busy, idle, borrow;
  bool operator==(const Signals&) const = default;
};

std::string show(const Signals& s) {
  return "strobe " + std::to_string(s.strobe) + " sel " + std::to_string(s.sel) + " count " +
         std::to_string(s.count) + " valid " + std::to_string(s.valid) + " valid_next " +
         std::to_string(s.valid_next) + " busy " +
         std::to_string(s.busy) + " idle " + std::to_string(s.idle) + " borrow " +
         std::to_string(s.borrow);
}

// Expected outputs in `cycle`, given the cycles in which a start was accepted.
Signals expected(int cycle, const std::vector<int>& accepted, int l) {
  Signals e{false, false, false, false, false, false, false, false};
  for (int s : accepted) {
    const int d = cycle - s;
    if (d >= 1 && d <= 1 + l) e.strobe = e.count = true;
    if (d >= 2 && d <= 1 + l) e.sel = true;
    if (d == 1 + l) e.borrow = true;
    if (d >= kValidFrom && d <= kValidFrom + l) e.valid = true;
    if (d >= kValidFrom - 1 && d <= kValidFrom - 1 + l) e.valid_next = true;
    if (d >= 1 && d <= kValidFrom + l) e.busy = true;
  }
  e.idle = !e.busy;
  return e;
}

// Drives start_i in the cycles of `starts`, simulates `cycles` cycles and compares every
// output in every cycle with the timing rules. `accepted` lists the starts that must
// take effect (the others fall into busy periods).
void run(int l, const std::vector<int>& starts, const std::vector<int>& accepted, int cycles) {
  Vcontrol dut;
  reset(dut);
  const std::set<int> start_set(starts.begin(), starts.end());
  int counter = l;  // counter 5, reloaded with l after every borrow
  int valid_cycles = 0, full_lines_valid = 0;
  for (int c = 0; c < cycles; ++c) {
    dut.start_i = start_set.count(c) ? 1 : 0;
    dut.borrow_i = 0;
    dut.eval();
    const bool borrow = dut.count_o && counter == 0;
    dut.borrow_i = borrow;
    dut.eval();
    const Signals got{static_cast<bool>(dut.strobe_o), static_cast<bool>(dut.sel_o),
                      static_cast<bool>(dut.count_o), static_cast<bool>(dut.valid_o),
                      static_cast<bool>(dut.valid_next_o),
                      static_cast<bool>(dut.busy_o), static_cast<bool>(dut.idle_o), borrow};
    const Signals want = expected(c, accepted, l);
    INFO("l = " << l << ", cycle " << c << "\n  got  " << show(got) << "\n  want "
                << show(want));
    REQUIRE(got == want);
    valid_cycles += got.valid;
    if (dut.count_o) counter = borrow ? l : counter - 1;
    tick(dut);
  }
  // Every line that ended inside the window delivered exactly l + 1 valid cycles.
  for (int s : accepted)
    if (s + kValidFrom + l < cycles) full_lines_valid += l + 1;
    else if (s + kValidFrom < cycles) full_lines_valid += cycles - (s + kValidFrom);
  CHECK(valid_cycles == full_lines_valid);
}

}  // namespace

TEST_CASE("control unit: one line, l = 0..3", "[rtl][control]") {
  const int l = GENERATE(0, 1, 2, 3);
  run(l, {2}, {2}, 20);
}

TEST_CASE("control unit: starts while busy are ignored", "[rtl][control]") {
  const int l = GENERATE(0, 1, 2, 3);
  // Start in cycle 1; extra pulses in every busy cycle (1 .. 6+l after it) are ignored;
  // the start in cycle 1+7+l (first idle cycle) is accepted back to back.
  const int next = 1 + kValidFrom + 1 + l;
  std::vector<int> starts;
  for (int c = 1; c <= next; ++c) starts.push_back(c);
  run(l, starts, {1, next}, 30);
}

TEST_CASE("control unit: a held start_i restarts as soon as the line ends", "[rtl][control]") {
  const int l = GENERATE(0, 3);
  std::vector<int> starts;
  for (int c = 0; c < 40; ++c) starts.push_back(c);
  std::vector<int> accepted;
  for (int s = 0; s < 40; s += kValidFrom + 1 + l) accepted.push_back(s);
  run(l, starts, accepted, 40);
}

TEST_CASE("control unit: reset leaves it idle", "[rtl][control]") {
  Vcontrol dut;
  reset(dut);
  dut.start_i = 0;
  dut.borrow_i = 0;
  for (int c = 0; c < 5; ++c) {
    dut.eval();
    CHECK(dut.busy_o == 0);
    CHECK(dut.idle_o == 1);
    CHECK(dut.strobe_o == 0);
    CHECK(dut.valid_o == 0);
    tick(dut);
  }
}
