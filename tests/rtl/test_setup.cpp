// SPDX-License-Identifier: Apache-2.0
// The hardware setup (rtl/specular_setup.sv, docs/setup_hw.md) against its golden model
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
#include "geo_cases.hpp"
#include "rtl_harness.hpp"
#include "setup_fixed.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>
#include <vector>

using namespace specular;
using geo_cases::kFmt;
using geo_cases::kGeo;
using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

struct Out {
  device::Span span;
  int status = 0;
  bool operator==(const Out& o) const {
    return span.reg.c == o.span.reg.c && span.reg.psi0 == o.span.reg.psi0 && span.reg.dpsi == o.span.reg.dpsi &&
           span.reg.n == o.span.reg.n && span.reg.len == o.span.reg.len && span.tag == o.span.tag && status == o.status;
  }
};

std::string show(const Out& o) {
  return "C " + std::to_string(o.span.reg.c) + " psi0 " + std::to_string(o.span.reg.psi0) + " dpsi " +
         std::to_string(o.span.reg.dpsi) + " n " + std::to_string(o.span.reg.n) + " len " + std::to_string(o.span.reg.len) +
         " tag " + std::to_string(o.span.tag) + " status " + std::to_string(o.status);
}

Out golden(const device::GeoSpan& g) {
  const host::fixed::Result r = host::fixed::setup_fixed(g, kGeo, kFmt);
  return {r.span, static_cast<int>(r.status)};
}

template <class M>
void drive(M& m, const device::GeoSpan& g) {
  m.geo_n1_i = device::pack_vec(g.n1, kGeo);
  m.geo_n2_i = device::pack_vec(g.n2, kGeo);
  m.geo_h1_i = device::pack_vec(g.h1, kGeo);
  m.geo_he_i = device::pack_vec(g.he, kGeo);
  m.geo_n_i = static_cast<uint16_t>(g.n);
  m.geo_len_i = static_cast<uint16_t>(g.len);
  m.geo_scale_i = static_cast<uint16_t>(g.scale);
  m.geo_tag_i = static_cast<uint16_t>(g.tag);
}

template <class M>
Out read(const M& m) {
  Out o;
  o.span.reg.c = m.span_c_o;
  o.span.reg.psi0 = static_cast<int32_t>(m.span_psi0_o);
  o.span.reg.dpsi = static_cast<int32_t>(m.span_dpsi_o);
  o.span.reg.n = m.span_n_o;
  o.span.reg.len = m.span_len_o;
  o.span.tag = m.span_tag_o;
  o.status = m.span_status_o;
  return o;
}

struct Stats {
  size_t accepted = 0, checked = 0, mismatches = 0, hold_violations = 0, resets = 0;
  std::string first_mismatch;
};

// Offers `spans` in order (each held until accepted), with the given probabilities per
// cycle of offering, of span_ready_i and of an asynchronous reset; spans in flight at a reset
// are dropped, the one offered is offered again. Ends with span_ready_i high until empty.
template <class M>
Stats run(M& m, const std::vector<device::GeoSpan>& spans, double p_valid, double p_ready, double p_reset, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Stats st;
  std::deque<Out> expected;
  reset(m);
  size_t next = 0;
  bool offering = false, prev_stalled = false;
  Out prev_out;
  long idle = 0;
  while (next < spans.size() || !expected.empty()) {
    if (!offering && next < spans.size() && u01(rng) < p_valid) offering = true;
    m.geo_valid_i = offering;
    if (offering) drive(m, spans[next]);
    const bool draining = next >= spans.size();
    m.span_ready_i = draining || u01(rng) < p_ready;
    m.eval();
    if (prev_stalled && (!m.span_valid_o || !(read(m) == prev_out))) ++st.hold_violations;
    if (m.span_valid_o) {
      prev_out = read(m);
      prev_stalled = !m.span_ready_i;
      if (m.span_ready_i) {
        ++st.checked;
        if (expected.empty() || !(expected.front() == prev_out)) {
          if (st.mismatches++ == 0)
            st.first_mismatch = "got " + show(prev_out) + ", expected " + (expected.empty() ? "nothing" : show(expected.front()));
        }
        if (!expected.empty()) expected.pop_front();
      }
    } else {
      prev_stalled = false;
    }
    const bool accept = offering && m.geo_ready_o;
    tick(m);
    if (accept) {
      expected.push_back(golden(spans[next]));
      ++st.accepted, ++next, offering = false;
    }
    if (p_reset > 0.0 && u01(rng) < p_reset) {
      reset(m);
      expected.clear();
      prev_stalled = false;
      ++st.resets;
    }
    if (++idle > static_cast<long>(40 * spans.size() + 10000)) break;  // a hang fails below
  }
  return st;
}

std::vector<device::GeoSpan> hard_spans() {
  std::vector<device::GeoSpan> v;
  for (const auto& h : geo_cases::hard_cases()) v.push_back(h.g);
  return v;
}

}  // namespace

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
  const char* env = std::getenv("SPECULAR_SETUP_RTL_SPANS");
  const size_t total = env ? std::strtoull(env, nullptr, 10) : 20000;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(total, 424242);
  const std::vector<device::GeoSpan> hard = hard_spans();
  for (size_t i = 0; i < hard.size(); ++i) spans.at((i * 7919) % spans.size()) = hard[i];
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
