// SPDX-License-Identifier: Apache-2.0
#include "stream_stage.hpp"

#include <cmath>
#include <cstdio>

namespace specular::sim {

const char* stream_kind_name(int kind) {
  static const char* names[kNumStreamKinds] = {"burst_short", "burst_mixed", "toggle",
                                               "random",      "long_stall",  "short_random"};
  return kind >= 0 && kind < kNumStreamKinds ? names[kind] : "?";
}

device::Span random_span(const device::Format& f, std::mt19937_64& rng, bool short_only) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  device::Span s;
  auto& r = s.reg;
  r.c = static_cast<uint32_t>(rng() & ((1ULL << f.c_bits) - 1));
  // psi0: mostly inside the lobe, some near 0 (the peak), some anywhere in the format.
  const double pick = u01(rng);
  if (pick < 0.6) {
    r.psi0 = device::quantize_angle(-2.0 + 4.0 * u01(rng), f);
  } else if (pick < 0.85) {
    r.psi0 = device::quantize_angle((u01(rng) - 0.5) * 1e-3, f);
  } else {
    const int64_t half = int64_t{1} << (f.angle_bits - 1);
    r.psi0 = static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * half)) - half;
  }
  // dpsi: log-uniform magnitude from 2^-28 to 2^-2 rad, either sign.
  const double mag = std::ldexp(1.0, -28 + static_cast<int>(rng() % 27)) * (1.0 + u01(rng));
  r.dpsi = device::quantize_angle((rng() & 1) ? mag : -mag, f);
  // n: valid, the decoder boundaries, or invalid codes.
  const double pn = u01(rng);
  static const uint32_t edges[] = {1, 2, 3, 6, 7, 1000, 0, 1001, 1023};
  if (pn < 0.85) r.n = 1 + static_cast<uint32_t>(rng() % 1000);
  else r.n = edges[rng() % std::size(edges)];
  r.n &= (1U << f.n_bits) - 1;
  // l: short spans dominate a rasterizer's output; a few long ones reach the counter maximum.
  const uint32_t lmax = static_cast<uint32_t>(f.max_len());
  const double pl = u01(rng);
  if (short_only || pl < 0.6) r.len = static_cast<uint32_t>(rng() % 4);
  else if (pl < 0.98) r.len = 4 + static_cast<uint32_t>(rng() % 28);
  else if (pl < 0.999) r.len = 32 + static_cast<uint32_t>(rng() % 224);
  else r.len = (rng() & 1) ? lmax : static_cast<uint32_t>(rng() % (lmax + 1));
  s.tag = static_cast<uint32_t>(rng());
  return s;
}

nlohmann::json StreamStats::to_json() const {
  nlohmann::json j = {{"spans", c.spans_accepted},
                      {"pixels", c.pixels},
                      {"cycles", c.cycles},
                      {"mismatches", c.mismatches},
                      {"protocol_errors", c.protocol_errors},
                      {"resets", c.resets},
                      {"dropped_by_reset", c.dropped},
                      {"max_l", max_l},
                      {"pixels_per_clock_short_spans", short_spans.per_clock_fill()},
                      {"pixels_per_clock_short_spans_steady", short_spans.per_clock_steady()},
                      {"pixels_per_clock_mixed_spans", mixed_spans.per_clock_fill()},
                      {"pixels_per_clock_mixed_spans_steady", mixed_spans.per_clock_steady()},
                      {"seconds", seconds},
                      {"ok", ok()}};
  for (int k = 0; k < kNumStreamKinds; ++k)
    j["segments"][stream_kind_name(k)] = {{"segments", segments[k]}, {"spans", kind_spans[k]}};
  return j;
}

nlohmann::json SceneStreamStats::to_json() const {
  return {{"spans", spans},
          {"pixels", pixels},
          {"stream_cycles", stream_cycles},
          {"stream_clocks_per_pixel", pixels ? double(stream_cycles) / pixels : 0.0},
          {"register_cycles", register_cycles},
          {"register_clocks_per_pixel", pixels ? double(register_cycles) / pixels : 0.0},
          {"mismatches", mismatches},
          {"protocol_errors", protocol_errors},
          {"ok", ok()}};
}

void print_stream_summary(const StreamStats& s, const std::vector<SceneStreamStats>& scenes, const std::string& config) {
  const auto& c = s.c;
  std::printf("\nStream stage (specular_stream, %s build): random spans, gaps, px_ready_i patterns, resets\n",
              config.c_str());
  std::printf("  spans accepted %llu (target %llu), pixels checked %llu, cycles %llu, max l %llu\n",
              (unsigned long long)c.spans_accepted, (unsigned long long)s.spans_target, (unsigned long long)c.pixels,
              (unsigned long long)c.cycles, (unsigned long long)s.max_l);
  std::printf("  segments:");
  for (int k = 0; k < kNumStreamKinds; ++k)
    std::printf(" %s %llu (%llu spans)%s", stream_kind_name(k), (unsigned long long)s.segments[k],
                (unsigned long long)s.kind_spans[k], k + 1 < kNumStreamKinds ? "," : "\n");
  std::printf("  resets mid-stream %llu (golden pixels dropped %llu)\n", (unsigned long long)c.resets,
              (unsigned long long)c.dropped);
  std::printf("  bit-exact mismatches %llu, protocol errors (tag/last/order/handshake) %llu\n",
              (unsigned long long)c.mismatches, (unsigned long long)c.protocol_errors);
  for (const auto& e : c.first_errors) std::printf("    %s\n", e.c_str());
  std::printf("  pixels per clock, px_ready_i high, spans back to back: l = 0..3: %.4f (%.4f without the fill latency)"
              ", mixed l: %.4f (%.4f)\n",
              s.short_spans.per_clock_fill(), s.short_spans.per_clock_steady(), s.mixed_spans.per_clock_fill(),
              s.mixed_spans.per_clock_steady());
  std::printf("  %.2f s, %.3e simulated cycles/s, result %s\n", s.seconds, s.seconds > 0 ? c.cycles / s.seconds : 0.0,
              s.ok() ? "PASS" : "FAIL");
  if (scenes.empty()) return;
  std::printf("\nScenes through the stream (spans back to back, px_ready_i high) against the register interface:\n");
  std::printf("| %-14s | %8s | %9s | %-22s | %-26s | %10s | %-6s |\n", "scene", "spans", "pixels", "stream clocks/pixel",
              "register clocks/pixel (l+L+1)", "mismatches", "result");
  std::printf("|----------------|----------|-----------|------------------------|----------------------------|------------|--------|\n");
  uint64_t px = 0, sc = 0, rc = 0;
  for (const auto& x : scenes) {
    std::printf("| %-14s | %8llu | %9llu | %-22.4f | %-26.4f | %10llu | %-6s |\n", x.name.c_str(),
                (unsigned long long)x.spans, (unsigned long long)x.pixels,
                x.pixels ? double(x.stream_cycles) / x.pixels : 0.0,
                x.pixels ? double(x.register_cycles) / x.pixels : 0.0,
                (unsigned long long)(x.mismatches + x.protocol_errors), x.ok() ? "PASS" : "FAIL");
    px += x.pixels;
    sc += x.stream_cycles;
    rc += x.register_cycles;
  }
  std::printf("| %-14s | %8s | %9llu | %-22.4f | %-26.4f | %10s | %-6s |\n", "all", "", (unsigned long long)px,
              px ? double(sc) / px : 0.0, px ? double(rc) / px : 0.0, "", "");
}

}  // namespace specular::sim
