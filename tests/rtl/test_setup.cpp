// SPDX-License-Identifier: Apache-2.0
// The hardware setup (rtl/setup/specular_setup.sv, docs/setup_hw.md#the-datapath)
// against its golden model host::fixed::setup_fixed, bit for bit: every descriptor field and the
// status of every span, in order, on the hard cases (tests/model/geo_cases.hpp) and the
// near-degenerate spans the model's test runs, back to back and under backpressure; on
// random spans under random input gaps, backpressure and resets; the AXI4-Stream rules on the
// descriptor side; and the throughput, one span per clock with span_ready_i high.
// SPECULAR_SETUP_RTL_SPANS=N runs N random spans instead of 20,000; the LUT-tree variant
// (TileBits = 0) is built and tested with -DSPECULAR_SETUP_VARIANTS=ON.
#include "Vsetup.h"
#include "Vsetup_ii16.h"
#include "Vsetup_ii32.h"
#include "Vsetup_ii64.h"
#include "Vsetup_ii8.h"
#if SPECULAR_SETUP_VARIANTS
#include "Vsetup_lut.h"
#endif
#include "setup_rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <tuple>
#include <vector>

using namespace specular;
using namespace specular::setup_rtl;
using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

std::vector<device::GeoSpan> hard_and_near_degenerate() {
  std::vector<device::GeoSpan> v = hard_spans();
  for (const auto& g : geo_cases::near_degenerate_spans()) v.push_back(g);
  for (size_t i = 0; i < v.size(); ++i) v[i].tag = static_cast<uint32_t>(i);
  return v;
}

}  // namespace

TEST_CASE("setup RTL: hard and near-degenerate cases bit-exact, back to back and under backpressure",
          "[setup_rtl]") {
  Vsetup m;
  const std::vector<device::GeoSpan> spans = hard_and_near_degenerate();
  // Every status of the golden model appears among them.
  std::vector<int> seen(5, 0);
  for (const auto& g : spans) seen.at(static_cast<size_t>(golden(g).status))++;
  for (int s : seen) CHECK(s > 0);
  const double p_ready = GENERATE(1.0, 0.5);
  const Stats st = run(m, spans, 1.0, p_ready, 0.0, 5);
  INFO(st.first_mismatch);
  WARN("specular_setup, ready " << p_ready << ": " << st.checked << " hard and near-degenerate descriptors checked, "
                                     << st.mismatches << " mismatches");
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
  WARN("specular_setup, valid " << mode.p_valid << ", ready " << mode.p_ready << ", reset " << mode.p_reset << ": "
                                     << st.checked << " descriptors checked bit for bit, " << st.mismatches
                                     << " mismatches, " << st.resets << " resets");
  CHECK(st.accepted == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
  if (mode.p_reset == 0.0) CHECK(st.checked == spans.size());
  else CHECK(st.resets > 0);
}

#if SPECULAR_SETUP_VARIANTS
TEST_CASE("setup RTL with LUT-tree multipliers (TileBits = 0): bit-exact", "[setup_rtl]") {
  Vsetup_lut m;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(5000, 31337);
  for (const auto& g : hard_and_near_degenerate()) spans.push_back(g);
  const Stats st = run(m, spans, 0.9, 0.7, 0.0, 17);
  INFO(st.first_mismatch);
  WARN("specular_setup, TileBits 0: " << st.checked << " descriptors checked bit for bit, " << st.mismatches
                                          << " mismatches");
  CHECK(st.checked == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
}
#endif  // SPECULAR_SETUP_VARIANTS

TEST_CASE("setup RTL: one span per clock with span_ready_i high", "[setup_rtl]") {
  Vsetup m;
  reset(m);
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(3000, 77);
  size_t next = 0, out = 0, mismatches = 0;
  long cycle = 0, first_accept = -1, first_out = -1, last_out = -1, not_ready = 0;
  while (out < spans.size() && cycle < 100000) {
    m.geo_valid_i = next < spans.size();
    if (next < spans.size()) drive(m, spans[next]);
    m.span_ready_i = 1;
    m.eval();
    if (m.span_valid_o) {
      if (first_out < 0) first_out = cycle;
      last_out = cycle;
      mismatches += !(read(m) == golden(spans[out]));
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
  WARN("specular_setup: latency " << latency << " clocks from the accept edge's cycle to the descriptor; " << out
                                       << " spans in " << (last_out - first_out + 1) << " clocks");
  CHECK(out == spans.size());
  CHECK(mismatches == 0);
  CHECK(not_ready == 0);
  CHECK(last_out - first_out + 1 == static_cast<long>(spans.size()));  // one per clock, no bubble
}

// The folded setup (SetupII = K): the same checks, and one span accepted every K clocks.
namespace {
struct FoldII8 {
  using Model = Vsetup_ii8;
  static constexpr long kII = 8;
};
struct FoldII16 {
  using Model = Vsetup_ii16;
  static constexpr long kII = 16;
};
struct FoldII32 {
  using Model = Vsetup_ii32;
  static constexpr long kII = 32;
};
// The CORDICs of one segment each (specular_setup_pkg::cordic_segs).
struct FoldII64 {
  using Model = Vsetup_ii64;
  static constexpr long kII = 64;
};
using FoldModels = std::tuple<FoldII8, FoldII16, FoldII32, FoldII64>;

size_t fold_spans() {
  const char* e = std::getenv("SPECULAR_SETUP_RTL_SPANS");
  return e != nullptr ? static_cast<size_t>(std::strtoul(e, nullptr, 10)) : 5000;
}
}  // namespace

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: hard and near-degenerate cases bit-exact", "[setup_rtl]",
                        FoldModels) {
  typename TestType::Model m;
  const std::vector<device::GeoSpan> spans = hard_and_near_degenerate();
  const double p_ready = GENERATE(1.0, 0.5);
  const Stats st = run(m, spans, 1.0, p_ready, 0.0, 5);
  INFO("SetupII " << TestType::kII << ": " << st.first_mismatch);
  WARN("specular_setup SetupII " << TestType::kII << ", ready " << p_ready << ": " << st.checked
                                      << " hard and near-degenerate descriptors checked, " << st.mismatches
                                      << " mismatches");
  CHECK(st.accepted == spans.size());
  CHECK(st.checked == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
}

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: random spans bit-exact under random gaps, backpressure and resets",
                        "[setup_rtl]", FoldModels) {
  typename TestType::Model m;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(fold_spans(), 4242);
  for (const auto& g : hard_and_near_degenerate()) spans.push_back(g);
  struct Mode {
    double p_valid, p_ready, p_reset;
  };
  const Mode mode = GENERATE(Mode{1.0, 1.0, 0.0}, Mode{0.7, 0.6, 0.0}, Mode{0.9, 0.8, 0.0001});
  const Stats st = run(m, spans, mode.p_valid, mode.p_ready, mode.p_reset, 99);
  INFO("SetupII " << TestType::kII << ": " << st.first_mismatch);
  WARN("specular_setup SetupII " << TestType::kII << ", valid " << mode.p_valid << ", ready " << mode.p_ready
                                      << ", reset " << mode.p_reset << ": " << st.checked
                                      << " descriptors checked bit for bit, " << st.mismatches << " mismatches, "
                                      << st.resets << " resets");
  CHECK(st.accepted == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
  if (mode.p_reset == 0.0) CHECK(st.checked == spans.size());
  else CHECK(st.resets > 0);
}

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: one span every SetupII clocks with span_ready_i high",
                        "[setup_rtl]", FoldModels) {
  typename TestType::Model m;
  reset(m);
  const long ii = TestType::kII;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(400, 78);
  size_t next = 0, out = 0, mismatches = 0;
  long cycle = 0, first_accept = -1, last_accept = -1, first_out = -1, last_out = -1, bad_gaps = 0, bad_out_gaps = 0;
  while (out < spans.size() && cycle < 1000000) {
    m.geo_valid_i = next < spans.size();
    if (next < spans.size()) drive(m, spans[next]);
    m.span_ready_i = 1;
    m.eval();
    if (m.span_valid_o) {
      if (first_out < 0) first_out = cycle;
      else if (cycle - last_out != ii) ++bad_out_gaps;
      last_out = cycle;
      mismatches += !(read(m) == golden(spans[out]));
      ++out;
    }
    if (next < spans.size() && m.geo_ready_o) {
      if (first_accept < 0) first_accept = cycle;
      else if (cycle - last_accept != ii) ++bad_gaps;
      last_accept = cycle;
      ++next;
    }
    tick(m);
    ++cycle;
  }
  const double measured = static_cast<double>(last_accept - first_accept) / static_cast<double>(spans.size() - 1);
  WARN("specular_setup SetupII " << ii << ": latency " << (first_out - first_accept) << " clocks; "
                                      << spans.size() << " spans accepted, one per " << measured
                                      << " clocks; outputs " << out << " in " << (last_out - first_out + 1) << " clocks");
  CHECK(out == spans.size());
  CHECK(mismatches == 0);
  CHECK(bad_gaps == 0);
  CHECK(bad_out_gaps == 0);
  CHECK(last_accept - first_accept == ii * static_cast<long>(spans.size() - 1));
}
