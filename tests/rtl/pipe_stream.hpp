// SPDX-License-Identifier: Apache-2.0
// Streaming check of a pipelined RTL block with a clock enable (en_i).
//
// Item j enters at the j-th enabled clock edge (the inputs of that cycle) and must be on the
// outputs after `latency` enabled edges, i.e. in every cycle in which exactly j + latency
// enabled edges have happened, however many stalled cycles (en_i low) lie in between. In
// stalled cycles the inputs are set to garbage that must reach no output. The check runs in
// every cycle, so it catches a wrong latency, a stage that moves while stalled (an item
// lost, duplicated or overwritten by the garbage) and a stage that holds while enabled.
// Cycle convention as in rtl_harness.hpp: inputs, eval(), read outputs, tick().
#pragma once

#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace specular::rtl_test {

// apply(model, item) sets the inputs of an item; garbage(model) sets arbitrary inputs;
// check(model, item) returns "" when the outputs hold the item's expected result, else a
// description; fill(model) (called while the first item is still in flight) likewise for the
// outputs of an empty pipeline ("" to accept anything). en(cycle) decides en_i.
// Returns the number of failed checks (the first few are reported through Catch).
template <class Model, class Item, class Apply, class Garbage, class Check, class Fill, class En>
int run_stream(Model& m, int latency, const std::vector<Item>& items, Apply apply, Garbage garbage,
               Check check, Fill fill, En en) {
  std::size_t edges = 0;
  int failures = 0;
  auto report = [&](const std::string& what, long cycle) {
    if (!what.empty() && ++failures <= 8) {
      FAIL_CHECK("cycle " << cycle << ", " << edges << " enabled edges: " << what);
    }
  };
  const std::size_t total = items.size() + static_cast<std::size_t>(latency);
  for (long cycle = 0; edges < total; ++cycle) {
    const bool e = en(cycle);
    m.en_i = e;
    if (e && edges < items.size()) {
      apply(m, items[edges]);
    } else {
      garbage(m);  // stalled, or flushing after the last item: must reach no output
    }
    m.eval();
    if (edges >= static_cast<std::size_t>(latency)) {
      report(check(m, items[edges - static_cast<std::size_t>(latency)]), cycle);
    } else {
      report(fill(m), cycle);
    }
    tick(m);
    if (e) ++edges;
  }
  return failures;
}

}  // namespace specular::rtl_test
