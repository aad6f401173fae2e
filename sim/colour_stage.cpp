// SPDX-License-Identifier: Apache-2.0
// Colour stage of the regression (colour_stage.hpp).
#include "colour_stage.hpp"

#include "setup_batch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

namespace specular::sim {

std::vector<RgbSpan> rgb_spans(const LoadedScene& ls, const device::Format& f, uint64_t tag_mask, uint64_t& saturated) {
  std::vector<RgbSpan> out;
  out.reserve(ls.raster.spans.size());
  const double top = std::ldexp(1.0, f.c_bits) - 1.0;
  for (size_t j = 0; j < ls.raster.spans.size(); ++j) {
    const Span& s = ls.raster.spans[j];
    ScanlineInput in = s.setup_in;
    in.is = in.ks = in.norm = 1.0;  // C = A^n: the device's unit intensity (device_unit_specular)
    RgbSpan r{{host::span_registers(in, f), static_cast<uint32_t>(j & tag_mask)}, {}};
    const glm::dvec3 colour = span_specular_colour(ls.scene, s);
    bool sat = false;
    for (int ch = 0; ch < 3; ++ch) {
      const double c = std::round(static_cast<double>(r.span.reg.c) * colour[ch]);
      sat = sat || c > top;
      r.c[ch] = static_cast<uint32_t>(std::clamp(c, 0.0, top));
    }
    saturated += sat ? 1 : 0;
    out.push_back(r);
  }
  return out;
}

ColourStats finish_colour(const LoadedScene& ls, const device::DeviceModel& dm, const std::vector<RgbSpan>& spans,
                          const RgbRun& run, const std::string& config, const std::string& images_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  ColourStats st;
  st.scene = ls.scene.name;
  st.config = config;
  st.spans = spans.size();
  st.pixels = run.px.size();
  st.protocol_errors = run.protocol_errors;
  // Every returned pixel against the golden model, channel by channel, with its tag and last flag.
  std::unordered_map<const Span*, uint64_t> first;  // raster span -> its first pixel in the run
  std::unordered_map<const Span*, size_t> index;    // raster span -> its RgbSpan
  uint64_t k = 0;
  for (size_t j = 0; j < spans.size(); ++j) {
    first[&ls.raster.spans[j]] = k;
    index[&ls.raster.spans[j]] = j;
    const device::Registers& r = spans[j].span.reg;
    for (uint32_t i = 0; i <= r.len; ++i, ++k) {
      if (k >= run.px.size()) continue;  // counted as a protocol error
      if (run.px[k] != dm.rgb_pixel(r, spans[j].c, static_cast<int>(i)) || run.tag[k] != spans[j].span.tag ||
          (run.last[k] != 0) != (i == r.len))
        ++st.mismatches;
    }
  }
  // The returned channels as the composition's specular term of each span.
  const SpecularEvaluator rtl = [&](const Span& s, std::span<glm::dvec3> out) {
    const auto it = first.find(&s);
    if (it == first.end()) throw std::logic_error("colour stage: a span outside the raster");
    for (size_t i = 0; i < out.size(); ++i) {
      const uint64_t p = it->second + i;
      if (p >= run.px.size()) continue;
      for (int ch = 0; ch < 3; ++ch) out[i][ch] = device::c_value(run.px[p][ch], dm.format());
    }
  };
  // C_ch cos^n(psi_i) in double, psi_i = psi0 + i dpsi of the span's registers (0 at or past pi/2).
  const device::Format& f = dm.format();
  const SpecularEvaluator exact = [&](const Span& s, std::span<glm::dvec3> out) {
    const auto it = index.find(&s);
    if (it == index.end()) throw std::logic_error("colour stage: a span outside the raster");
    const RgbSpan& rs = spans[it->second];
    const device::Registers& r = rs.span.reg;
    for (size_t i = 0; i < out.size(); ++i) {
      const double psi = device::angle_value(r.psi0 + static_cast<int64_t>(i) * r.dpsi, f);
      const double shape = std::abs(psi) < std::numbers::pi / 2 ? std::pow(std::cos(psi), static_cast<double>(r.n)) : 0.0;
      for (int ch = 0; ch < 3; ++ch) out[i][ch] = device::c_value(rs.c[ch], f) * shape;
    }
  };
  const ColourLayers got = compose_specular(ls.scene, ls.raster, rtl);
  const ColourLayers ref = compose(ls.scene, ls.raster, reference_unit_specular(ls.scene));
  const ColourLayers own = compose_specular(ls.scene, ls.raster, exact);
  st.err = srgb_code_error(got.image, ref.image);
  st.device_err = srgb_code_error(got.image, own.image);
  if (!images_dir.empty()) {
    std::filesystem::create_directories(images_dir);
    const std::string base = images_dir + "/" + ls.scene.name + "_colour_";
    write_srgb_png(base + "rtl.png", got.image);
    write_srgb_png(base + "reference.png", ref.image);
    write_code_diff_png(base + "diff.png", got.image, ref.image, "RTL - REFERENCE (SRGB CODES) " + config);
    write_srgb_png(base + "registers.png", own.image);
    write_code_diff_png(base + "device_diff.png", got.image, own.image, "RTL - EXACT");
    st.images = {base + "rtl.png", base + "reference.png", base + "diff.png", base + "registers.png",
                 base + "device_diff.png"};
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return st;
}

nlohmann::json ColourStats::to_json() const {
  return {{"config", config},
          {"spans", spans},
          {"pixels", pixels},
          {"mismatches", mismatches},
          {"protocol_errors", protocol_errors},
          {"saturated_spans", saturated_spans},
          {"covered_pixels", err.pixels},
          {"srgb8_max", err.max_abs},
          {"srgb8_mean", err.mean_abs},
          {"linear_max", err.max_linear},
          {"device_linear_max", device_err.max_linear},
          {"device_srgb8_max", device_err.max_abs},
          {"images", images},
          {"ok", ok()}};
}

void print_colour_table(const std::vector<ColourStats>& rows) {
  std::printf("\nColour (every span through specular_stream with Channels = 3, C = its specular colour x A^n; the returned\n"
              "channels summed per light on the host beside emission, ambient and Lambert diffuse; against the same\n"
              "composition around the material's BRDF in double; 8-bit sRGB codes over the covered pixels; the device\n"
              "alone: against the composition around C cos^n(psi) of its registers, worst linear difference of full scale):\n");
  std::printf("| %-14s | %-11s | %7s | %8s | %10s | %8s | %-14s | %-20s | %-12s | %-6s |\n", "scene", "config", "spans",
              "pixels", "mismatches", "C sat.", "worst R/G/B", "mean R/G/B", "device alone", "result");
  std::printf("|----------------|-------------|---------|----------|------------|----------|----------------|----------------------|--------------|--------|\n");
  for (const auto& r : rows) {
    char worst[32], mean[48];
    std::snprintf(worst, sizeof worst, "%d/%d/%d", r.err.max_abs[0], r.err.max_abs[1], r.err.max_abs[2]);
    std::snprintf(mean, sizeof mean, "%.3f/%.3f/%.3f", r.err.mean_abs[0], r.err.mean_abs[1], r.err.mean_abs[2]);
    const double dev = std::max({r.device_err.max_linear[0], r.device_err.max_linear[1], r.device_err.max_linear[2]});
    std::printf("| %-14s | %-11s | %7llu | %8llu | %10llu | %8llu | %-14s | %-20s | %12.3e | %-6s |\n", r.scene.c_str(),
                r.config.c_str(), (unsigned long long)r.spans, (unsigned long long)r.pixels,
                (unsigned long long)(r.mismatches + r.protocol_errors), (unsigned long long)r.saturated_spans, worst, mean,
                dev, r.ok() ? "PASS" : "FAIL");
  }
}

}  // namespace specular::sim
