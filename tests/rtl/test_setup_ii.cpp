// SPDX-License-Identifier: Apache-2.0
// specular_setup with SetupII = 2, 4 and 8 (rtl/setup/specular_setup.sv,
// docs/setup_hw.md#sharing-over-setupii-clocks) against its golden model
// host::fixed::setup_fixed, bit for bit, with the checks of tests/rtl/test_setup.cpp (the
// hard cases; random spans under random gaps, backpressure and resets) and the rate: spans
// offered back to back with span_ready_i high are accepted exactly one every SetupII clocks.
// make test builds SetupII = 8 only (every block shared: one normalizer for the six sites);
// -DSPECULAR_SETUP_VARIANTS=ON adds SetupII = 2, 4 and 4 with HeEqH1 = 1 (three code
// normalizer sites). SPECULAR_SETUP_RTL_SPANS=N runs N random spans instead of 20,000.
#include "Vsetup_ii8.h"
#if SPECULAR_SETUP_VARIANTS
#include "Vsetup_ii2.h"
#include "Vsetup_ii4.h"
#include "Vsetup_ii4_he1.h"
#endif
#include "setup_rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <tuple>
#include <vector>

using namespace specular;
using namespace specular::setup_rtl;

namespace {

template <class M, int K>
struct Ii {
  using Model = M;
  static constexpr int kII = K;
};
using Ii8 = Ii<Vsetup_ii8, 8>;
#if SPECULAR_SETUP_VARIANTS
using Ii2 = Ii<Vsetup_ii2, 2>;
using Ii4 = Ii<Vsetup_ii4, 4>;
using Models = std::tuple<Ii2, Ii4, Ii8>;
#else
using Models = std::tuple<Ii8>;
#endif

}  // namespace

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: hard cases bit-exact, back to back and under backpressure", "[setup_rtl_ii]",
                        Models) {
  typename TestType::Model m;
  const std::vector<device::GeoSpan> spans = hard_spans();
  const double p_ready = GENERATE(1.0, 0.5);
  const Stats st = run(m, spans, 1.0, p_ready, 0.0, 5);
  INFO("SetupII " << TestType::kII << ": " << st.first_mismatch);
  CHECK(st.accepted == spans.size());
  CHECK(st.checked == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
}

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: random spans bit-exact under random gaps, backpressure and resets",
                        "[setup_rtl_ii]", Models) {
  typename TestType::Model m;
  const std::vector<device::GeoSpan> spans = random_spans_with_hard_cases();
  struct Mode {
    double p_valid, p_ready, p_reset;
  };
  const Mode mode = GENERATE(Mode{1.0, 1.0, 0.0}, Mode{0.7, 0.6, 0.0}, Mode{0.9, 0.8, 0.0005});
  const Stats st = run(m, spans, mode.p_valid, mode.p_ready, mode.p_reset, 99);
  INFO(st.first_mismatch);
  INFO("SetupII " << TestType::kII << ", valid " << mode.p_valid << ", ready " << mode.p_ready << ", reset "
                  << mode.p_reset << ": " << st.accepted << " accepted, " << st.checked << " checked, " << st.resets
                  << " resets");
  WARN("specular_setup SetupII " << TestType::kII << ", valid " << mode.p_valid << ", ready " << mode.p_ready
                                 << ", reset " << mode.p_reset << ": " << st.checked << " descriptors checked bit for bit, "
                                 << st.mismatches << " mismatches, " << st.resets << " resets");
  CHECK(st.accepted == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
  if (mode.p_reset == 0.0) CHECK(st.checked == spans.size());
  else CHECK(st.resets > 0);
}

TEMPLATE_LIST_TEST_CASE("setup RTL, SetupII > 1: one span every SetupII clocks with span_ready_i high", "[setup_rtl_ii]",
                        Models) {
  typename TestType::Model m;
  constexpr long k = TestType::kII;
  reset(m);
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(3000, 77);
  for (auto& g : spans) g.len = 0;
  std::vector<long> accepts, outs;
  size_t next = 0;
  long cycle = 0;
  while (outs.size() < spans.size() && cycle < 100000) {
    m.geo_valid_i = next < spans.size();
    if (next < spans.size()) drive(m, spans[next]);
    m.span_ready_i = 1;
    m.eval();
    if (m.span_valid_o) {
      CHECK(read(m) == golden(spans[outs.size()]));
      outs.push_back(cycle);
    }
    if (next < spans.size() && m.geo_ready_o) {
      accepts.push_back(cycle);
      ++next;
    }
    tick(m);
    ++cycle;
  }
  REQUIRE(outs.size() == spans.size());
  REQUIRE(accepts.size() == spans.size());
  // Offered from cycle 0 after reset: accepted at cycles 0, k, 2k, ...; out at the same rate.
  size_t bad_accept = 0, bad_out = 0;
  for (size_t i = 0; i < accepts.size(); ++i) bad_accept += accepts[i] != static_cast<long>(i) * k;
  for (size_t i = 1; i < outs.size(); ++i) bad_out += outs[i] - outs[i - 1] != k;
  const long latency = outs[0] - accepts[0];
  WARN("specular_setup SetupII " << k << ": latency " << latency << " clocks from the accept edge's cycle to the "
                                 << "descriptor; " << outs.size() << " spans in " << (outs.back() - outs.front() + 1)
                                 << " clocks");
  CHECK(bad_accept == 0);
  CHECK(bad_out == 0);
}

#if SPECULAR_SETUP_VARIANTS
TEST_CASE("setup RTL, SetupII 4 with HeEqH1: geo_he_i ignored, He = H1, bit-exact", "[setup_rtl_ii]") {
  Vsetup_ii4_he1 m;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(5000, 31337);
  const std::vector<device::GeoSpan> hard = hard_spans();
  spans.insert(spans.end(), hard.begin(), hard.end());
  const Stats st = run(m, spans, 0.8, 0.7, 0.0, 7, true);
  INFO(st.first_mismatch);
  CHECK(st.accepted == spans.size());
  CHECK(st.checked == spans.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
}
#endif
