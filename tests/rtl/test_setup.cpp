// SPDX-License-Identifier: Apache-2.0
// The hardware setup (rtl/setup/specular_setup.sv, docs/setup_hw.md) against its golden model
// host::fixed::setup_fixed, bit for bit: every descriptor field and the status of every span,
// in order, on the hard cases of docs/scanline_setup.md#hard-cases and random spans
// (tests/model/geo_cases.hpp), under random input gaps, random backpressure and random
// resets; the AXI4-Stream rules on the descriptor side (valid and data hold until the
// transfer); and the throughput, one span per clock with span_ready_i high.
// SPECULAR_SETUP_RTL_SPANS=N runs N random spans instead of 20,000 (the long option); the
// HeEqH1 variant is built and tested with -DSPECULAR_SETUP_VARIANTS=ON.
#include "Vsetup.h"
#if SPECULAR_SETUP_VARIANTS
#include "Vsetup_he1.h"
#endif
#include "setup_rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

using namespace specular;
using namespace specular::setup_rtl;
using geo_cases::kFmt;
using geo_cases::kGeo;
using specular::rtl_test::reset;
using specular::rtl_test::tick;

TEST_CASE("setup RTL: hard cases bit-exact, back to back and under backpressure", "[setup_rtl]") {
  Vsetup m;
  const std::vector<device::GeoSpan> spans = hard_spans();
  // The status each hard case must have: the golden model's is the scalar setup's
  // (tests/model/test_setup_fixed.cpp); here every one of the five appears.
  std::vector<int> seen(5, 0);
  for (const auto& g : spans) seen.at(static_cast<size_t>(golden(g).status))++;
  for (int s : seen) CHECK(s > 0);
  const double p_ready = GENERATE(1.0, 0.5);
  const Stats st = run(m, spans, 1.0, p_ready, 0.0, 5);
  INFO(st.first_mismatch);
  CHECK(st.accepted == spans.size());
  CHECK(st.checked == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
}

TEST_CASE("setup RTL: random spans bit-exact under random gaps, backpressure and resets", "[setup_rtl]") {
  Vsetup m;
  const std::vector<device::GeoSpan> spans = random_spans_with_hard_cases();
  struct Mode {
    double p_valid, p_ready, p_reset;
  };
  const Mode mode = GENERATE(Mode{1.0, 1.0, 0.0}, Mode{0.7, 0.6, 0.0}, Mode{0.9, 0.8, 0.0005});
  const Stats st = run(m, spans, mode.p_valid, mode.p_ready, mode.p_reset, 99);
  INFO(st.first_mismatch);
  INFO("valid " << mode.p_valid << ", ready " << mode.p_ready << ", reset " << mode.p_reset << ": " << st.accepted
                << " accepted, " << st.checked << " checked, " << st.resets << " resets");
  WARN("specular_setup, valid " << mode.p_valid << ", ready " << mode.p_ready << ", reset " << mode.p_reset << ": "
                                << st.checked << " descriptors checked bit for bit, " << st.mismatches << " mismatches, "
                                << st.resets << " resets");
  CHECK(st.accepted == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
  if (mode.p_reset == 0.0) CHECK(st.checked == spans.size());
  else CHECK(st.resets > 0);
}

#if SPECULAR_SETUP_VARIANTS
TEST_CASE("setup RTL with HeEqH1: geo_he_i ignored, He = H1, bit-exact", "[setup_rtl]") {
  Vsetup_he1 m;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(5000, 31337);
  const std::vector<device::GeoSpan> hard = hard_spans();
  spans.insert(spans.end(), hard.begin(), hard.end());
  // What the port carries is ignored: the golden model gets He = H1, the RTL garbage on geo_he_i.
  std::vector<device::GeoSpan> golden_in = spans;
  for (size_t i = 0; i < spans.size(); ++i) {
    golden_in[i].he = golden_in[i].h1;
    spans[i].he = {static_cast<int32_t>(i % 977) - 400, 7, -static_cast<int32_t>(i % 131)};
  }
  reset(m);
  std::deque<Out> expected;
  size_t next = 0, checked = 0, mismatches = 0;
  for (long cycle = 0; checked < spans.size() && cycle < 100000; ++cycle) {
    m.geo_valid_i = next < spans.size();
    if (next < spans.size()) drive(m, spans[next]);
    m.span_ready_i = (cycle % 3) != 1;
    m.eval();
    if (m.span_valid_o && m.span_ready_i) {
      mismatches += expected.empty() || !(read(m) == expected.front());
      if (!expected.empty()) expected.pop_front();
      ++checked;
    }
    const bool accept = next < spans.size() && m.geo_ready_o;
    tick(m);
    if (accept) expected.push_back(golden(golden_in[next++]));
  }
  CHECK(checked == spans.size());
  CHECK(mismatches == 0);
}
#endif  // SPECULAR_SETUP_VARIANTS

TEST_CASE("setup RTL: one span per clock with span_ready_i high", "[setup_rtl]") {
  Vsetup m;
  reset(m);
  // l = 0 spans back to back (and any others: the setup's rate does not depend on l).
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(3000, 77);
  for (auto& g : spans) g.len = 0;
  size_t next = 0, out = 0;
  long cycle = 0, first_accept = -1, first_out = -1, last_out = -1, not_ready = 0;
  while (out < spans.size() && cycle < 100000) {
    m.geo_valid_i = next < spans.size();
    if (next < spans.size()) drive(m, spans[next]);
    m.span_ready_i = 1;
    m.eval();
    if (m.span_valid_o) {
      if (first_out < 0) first_out = cycle;
      last_out = cycle;
      CHECK(read(m) == golden(spans[out]));
      ++out;
    }
    if (next < spans.size()) {
      if (m.geo_ready_o) {
        if (first_accept < 0) first_accept = cycle;
        ++next;
      } else {
        ++not_ready;
      }
    }
    tick(m);
    ++cycle;
  }
  const long latency = first_out - first_accept;
  WARN("specular_setup: latency " << latency << " clocks from the accept edge's cycle to the descriptor; "
                                  << out << " spans in " << (last_out - first_out + 1) << " clocks");
  CHECK(out == spans.size());
  CHECK(not_ready == 0);
  CHECK(last_out - first_out + 1 == static_cast<long>(spans.size()));  // one per clock, no bubble
}
