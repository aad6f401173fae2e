// SPDX-License-Identifier: Apache-2.0
// The hardware setup's block-test harness (tests/rtl/test_setup.cpp): drives geometry spans
// into a Verilator model of specular_setup (rtl/setup/) and checks every descriptor field and
// the status against its golden model host::fixed::setup_fixed, in order, under random input
// gaps, backpressure and resets.
#pragma once

#include "geo_cases.hpp"
#include "rtl_harness.hpp"
#include "setup_fixed.hpp"

#include <cstdint>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>
#include <vector>

namespace specular::setup_rtl {

using geo_cases::kFmt;
using geo_cases::kGeo;
using specular::rtl_test::reset;
using specular::rtl_test::tick;

struct Out {
  device::Span span;
  int status = 0;
  bool operator==(const Out& o) const {
    return span.reg.c == o.span.reg.c && span.reg.psi0 == o.span.reg.psi0 && span.reg.dpsi == o.span.reg.dpsi &&
           span.reg.n == o.span.reg.n && span.reg.len == o.span.reg.len && span.tag == o.span.tag && status == o.status;
  }
};

inline std::string show(const Out& o) {
  return "C " + std::to_string(o.span.reg.c) + " psi0 " + std::to_string(o.span.reg.psi0) + " dpsi " +
         std::to_string(o.span.reg.dpsi) + " n " + std::to_string(o.span.reg.n) + " len " + std::to_string(o.span.reg.len) +
         " tag " + std::to_string(o.span.tag) + " status " + std::to_string(o.status);
}

inline Out golden(const device::GeoSpan& g) {
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
    const bool taken = m.span_valid_o && m.span_ready_i;
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
    // A hang (no span accepted and no descriptor taken for 10,000 clocks, far beyond any
    // SetupII and latency) fails below.
    if (accept || taken) idle = 0;
    if (++idle > 10000) break;
  }
  return st;
}

inline std::vector<device::GeoSpan> hard_spans() {
  std::vector<device::GeoSpan> v;
  for (const auto& h : geo_cases::hard_cases()) v.push_back(h.g);
  return v;
}

// The random run of the block tests: SPECULAR_SETUP_RTL_SPANS spans (default 20,000) with the
// hard cases spread among them.
inline std::vector<device::GeoSpan> random_spans_with_hard_cases() {
  const char* env = std::getenv("SPECULAR_SETUP_RTL_SPANS");
  const size_t total = env ? std::strtoull(env, nullptr, 10) : 20000;
  std::vector<device::GeoSpan> spans = geo_cases::random_geo_spans(total, 424242);
  const std::vector<device::GeoSpan> hard = hard_spans();
  for (size_t i = 0; i < hard.size(); ++i) spans.at((i * 7919) % spans.size()) = hard[i];
  return spans;
}

}  // namespace specular::setup_rtl
