// SPDX-License-Identifier: Apache-2.0
// Colour stage of the regression (colour_stage.hpp).
#include "colour_stage.hpp"

#include "setup_batch.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace specular::sim {

std::vector<device::Span> unit_spans(const Raster& raster, const device::Format& f, uint64_t tag_mask) {
  std::vector<device::Span> out;
  out.reserve(raster.spans.size());
  for (size_t j = 0; j < raster.spans.size(); ++j) {
    ScanlineInput in = raster.spans[j].setup_in;
    in.is = in.ks = in.norm = 1.0;  // C = A^n: the device's unit intensity (device_unit_specular)
    out.push_back({host::span_registers(in, f), static_cast<uint32_t>(j & tag_mask)});
  }
  return out;
}

ColourStats finish_colour(const LoadedScene& ls, const device::DeviceModel& dm, const std::vector<device::Span>& spans,
                          const StreamRun& run, const std::string& config, const std::string& images_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  ColourStats st;
  st.scene = ls.scene.name;
  st.config = config;
  st.spans = spans.size();
  st.pixels = run.pixels;
  // Every recorded pixel against the golden model's stream of the same spans.
  std::unordered_map<const Span*, uint64_t> first;  // raster span -> its first pixel in the run
  std::vector<device::StreamPixel> golden;
  for (size_t j = 0; j < spans.size(); ++j) {
    first[&ls.raster.spans[j]] = golden.size();
    dm.stream_span(spans[j], golden);
  }
  for (uint64_t k = 0; k < golden.size(); ++k)
    if (k >= run.pixels || run.intensity[k] != golden[k].intensity || run.tag[k] != golden[k].tag ||
        (run.last[k] != 0) != golden[k].last)
      ++st.mismatches;
  if (run.pixels != golden.size()) st.mismatches += run.pixels > golden.size() ? run.pixels - golden.size() : 0;
  // The RTL's intensities as the composition's S_j (what device_unit_specular gives from the golden model).
  const Evaluator rtl = [&](const Span& s, std::span<double> out) {
    const auto it = first.find(&s);
    if (it == first.end()) throw std::logic_error("colour stage: a span outside the raster");
    for (size_t i = 0; i < out.size(); ++i) {
      const uint64_t k = it->second + i;
      out[i] = k < run.pixels ? device::c_value(run.intensity[k], dm.format()) : 0.0;
    }
  };
  const ColourLayers got = compose(ls.scene, ls.raster, rtl);
  const ColourLayers ref = compose(ls.scene, ls.raster, reference_unit_specular(ls.scene));
  st.err = srgb_code_error(got.image, ref.image);
  if (!images_dir.empty()) {
    std::filesystem::create_directories(images_dir);
    const std::string base = images_dir + "/" + ls.scene.name + "_colour_";
    write_srgb_png(base + "rtl.png", got.image);
    write_srgb_png(base + "reference.png", ref.image);
    write_code_diff_png(base + "diff.png", got.image, ref.image, "RTL - REFERENCE (SRGB CODES) " + config);
    st.images = {base + "rtl.png", base + "reference.png", base + "diff.png"};
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
          {"covered_pixels", err.pixels},
          {"srgb8_max", err.max_abs},
          {"srgb8_mean", err.mean_abs},
          {"images", images},
          {"ok", ok()}};
}

void print_colour_table(const std::vector<ColourStats>& rows) {
  std::printf("\nColour (every span once more through specular_stream at unit C, composed on the host: emission, ambient,\n"
              "Lambert diffuse + specular colour x light colour x the RTL's intensity per light; against the same\n"
              "composition around the material's BRDF in double; 8-bit sRGB codes over the covered pixels):\n");
  std::printf("| %-14s | %-8s | %7s | %8s | %10s | %-14s | %-20s | %-6s |\n", "scene", "config", "spans", "pixels",
              "mismatches", "worst R/G/B", "mean R/G/B", "result");
  std::printf("|----------------|----------|---------|----------|------------|----------------|----------------------|--------|\n");
  for (const auto& r : rows) {
    char worst[32], mean[48];
    std::snprintf(worst, sizeof worst, "%d/%d/%d", r.err.max_abs[0], r.err.max_abs[1], r.err.max_abs[2]);
    std::snprintf(mean, sizeof mean, "%.3f/%.3f/%.3f", r.err.mean_abs[0], r.err.mean_abs[1], r.err.mean_abs[2]);
    std::printf("| %-14s | %-8s | %7llu | %8llu | %10llu | %-14s | %-20s | %-6s |\n", r.scene.c_str(), r.config.c_str(),
                (unsigned long long)r.spans, (unsigned long long)r.pixels,
                (unsigned long long)(r.mismatches + r.protocol_errors), worst, mean, r.ok() ? "PASS" : "FAIL");
  }
}

}  // namespace specular::sim
