// SPDX-License-Identifier: Apache-2.0
// Stream stage of the regression: rtl/specular_stream under random spans, random gaps on
// span_valid_i, random px_ready_i patterns and random resets, every pixel checked by the
// scoreboard of stream_harness.hpp (bit-exact intensity, tag, last, count and order); and
// every scene's spans back to back through the stream (clocks per pixel next to the
// register interface's l + 7 per line).
//
// Segments, each of a random kind (the per-kind counts are printed):
//   burst_short   l = 0..3, spans always offered, px_ready_i always high (throughput)
//   burst_mixed   mixed l, spans always offered, px_ready_i always high (throughput)
//   toggle        px_ready_i toggling every clock, spans always offered
//   random        px_ready_i high with probability p, span gaps with probability q
//   long_stall    px_ready_i low for 20..400 clocks, then high for 1..50
//   short_random  back-to-back l = 0..3 spans under random px_ready_i
// In every kind but the bursts an asynchronous reset hits at random clocks (about one in
// 20,000), for 1..3 clocks, mid-stream.
#pragma once

#include "scene_stage.hpp"
#include "stream_harness.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace specular::sim {

enum StreamKind { kBurstShort, kBurstMixed, kToggle, kRandom, kLongStall, kShortRandom, kNumStreamKinds };
const char* stream_kind_name(int kind);

struct Throughput {
  uint64_t pixels = 0;
  uint64_t cycles_fill = 0;    // first accept .. last transfer, fill latency included
  uint64_t cycles_steady = 0;  // first transfer .. last transfer
  double per_clock_fill() const { return cycles_fill ? double(pixels) / cycles_fill : 0.0; }
  double per_clock_steady() const { return cycles_steady ? double(pixels) / cycles_steady : 0.0; }
};

struct StreamStats {
  StreamCounters c;
  uint64_t spans_target = 0;
  std::array<uint64_t, kNumStreamKinds> segments{}, kind_spans{};
  Throughput short_spans, mixed_spans;  // the burst kinds (ready always high)
  uint64_t max_l = 0;
  double seconds = 0.0;
  bool ok() const {
    return c.spans_accepted >= spans_target && c.mismatches == 0 && c.protocol_errors == 0 && c.pixels > 0 &&
           short_spans.per_clock_fill() >= 0.99 && mixed_spans.per_clock_fill() >= 0.99;
  }
  nlohmann::json to_json() const;
};

// A random span: registers over the whole input space the regression cares about
// (valid and invalid n, the decoder boundaries, angles near 0, in the lobe and far).
device::Span random_span(const device::Format& f, std::mt19937_64& rng, bool short_only);

struct SceneStreamStats {
  std::string name;
  uint64_t spans = 0, pixels = 0;
  uint64_t stream_cycles = 0;    // first accept .. last transfer, spans back to back
  uint64_t register_cycles = 0;  // the register interface: l + 7 per line (measured, scene stage)
  uint64_t mismatches = 0, protocol_errors = 0;
  bool ok() const { return pixels > 0 && mismatches == 0 && protocol_errors == 0; }
  nlohmann::json to_json() const;
};

void print_stream_summary(const StreamStats& s, const std::vector<SceneStreamStats>& scenes,
                          const std::string& config = "default");

namespace detail {
// Runs until the core has delivered every owed pixel (ready high, nothing offered).
template <class V>
void drain(StreamHarness<V>& h) {
  for (int guard = 0; !h.empty(); ++guard) {
    h.cycle(nullptr, true);
    if (guard > (1 << 16)) {
      h.error("the stream did not drain: " + std::to_string(h.owed()) + " pixels owed");
      return;
    }
  }
  for (int i = 0; i < 8; ++i) {
    bool t = false;
    h.cycle(nullptr, true, &t);  // a transfer here is checked (and fails) as a pixel without a span
  }
}
}  // namespace detail

template <class V>
StreamStats run_stream_stage(StreamHarness<V>& h, uint64_t seed, uint64_t spans) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto& f = h.model().format();
  StreamStats st;
  st.spans_target = spans;
  std::mt19937_64 rng(seed ^ 0x57ea3ULL);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const auto c0 = h.counters();
  uint64_t made = 0;
  while (made < spans) {
    // The two throughput bursts come first, so that even a short run measures them.
    const uint64_t seg_no = st.segments[kBurstShort] + st.segments[kBurstMixed] + st.segments[kToggle] +
                            st.segments[kRandom] + st.segments[kLongStall] + st.segments[kShortRandom];
    const int kind = seg_no < 2 ? static_cast<int>(seg_no) : static_cast<int>(rng() % kNumStreamKinds);
    const bool burst = kind == kBurstShort || kind == kBurstMixed;
    const bool short_only = kind == kBurstShort || kind == kShortRandom;
    const uint64_t n = std::min<uint64_t>(spans - made, burst ? (seg_no < 2 ? 500 : 1500) : 300 + rng() % 700);
    ++st.segments[kind];
    st.kind_spans[kind] += n;
    std::vector<device::Span> seg(n);
    for (auto& s : seg) {
      s = random_span(f, rng, short_only);
      st.max_l = std::max<uint64_t>(st.max_l, s.reg.len);
    }
    made += n;
    if (burst) detail::drain(h);  // throughput is measured from an empty pipeline
    const double p_ready = 0.1 + 0.85 * u01(rng), p_offer = 0.2 + 0.8 * u01(rng);
    const bool gaps = kind == kRandom;
    size_t next = 0;
    bool ready_phase = true;
    int phase_left = 0;
    uint64_t pixels = 0, first_accept = 0, first_fire = 0, last_fire = 0;
    bool any_accept = false, any_fire = false;
    bool offering = false;
    uint64_t guard = 0;
    while (next < seg.size() || (burst && !h.empty())) {
      bool ready = true;
      switch (kind) {
        case kToggle: ready = (h.now() & 1) != 0; break;
        case kRandom:
        case kShortRandom: ready = u01(rng) < p_ready; break;
        case kLongStall:
          if (phase_left-- <= 0) {
            ready_phase = !ready_phase;
            phase_left = ready_phase ? 1 + static_cast<int>(rng() % 50) : 20 + static_cast<int>(rng() % 381);
          }
          ready = ready_phase;
          break;
        default: break;
      }
      // Offer the next span (held until accepted); with gaps, a new offer starts only
      // with probability p_offer (never withdrawn once made: AXI source rule).
      if (!offering && next < seg.size()) offering = !gaps || u01(rng) < p_offer;
      const device::Span* offer = offering && next < seg.size() ? &seg[next] : nullptr;
      const uint64_t cyc = h.now();
      bool fired = false;
      if (h.cycle(offer, ready, &fired)) {
        if (!any_accept) first_accept = cyc;
        any_accept = true;
        ++next;
        offering = false;
      }
      if (fired) {
        if (!any_fire) first_fire = cyc;
        any_fire = true;
        last_fire = cyc;
        ++pixels;
      }
      if (!burst && rng() % 20000 == 0) {
        h.reset(1 + static_cast<int>(rng() % 3));
        offering = offering && next < seg.size();  // the offered span stays offered
        if (rng() & 1) {
          // Right after reset: empty, nothing comes out.
          for (int i = 0; i < 6; ++i) {
            h.cycle(nullptr, true);
          }
        }
      }
      if (++guard > 64ULL * (seg.size() + 64) * 1024) {
        h.error("segment did not finish");
        break;
      }
    }
    if (burst && any_fire) {
      Throughput& t = kind == kBurstShort ? st.short_spans : st.mixed_spans;
      t.pixels += pixels;
      t.cycles_fill += last_fire - first_accept + 1;
      t.cycles_steady += last_fire - first_fire + 1;
    }
  }
  detail::drain(h);
  const auto& c1 = h.counters();
  st.c = c1;
  st.c.cycles -= c0.cycles;
  st.c.spans_accepted -= c0.spans_accepted;
  st.c.pixels -= c0.pixels;
  st.c.mismatches -= c0.mismatches;
  st.c.protocol_errors -= c0.protocol_errors;
  st.c.resets -= c0.resets;
  st.c.dropped -= c0.dropped;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return st;
}

}  // namespace specular::sim
