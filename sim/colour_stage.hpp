// SPDX-License-Identifier: Apache-2.0
// Colour stage of the regression (docs/colour.md): every scene composed in colour around the
// RTL's specular intensities. Each span of each light goes through the verilated
// specular_stream once more with unit intensity (Is = ks = norm = 1, so C = A^n: what
// model/scene/compose.hpp's device_unit_specular feeds the golden model), every pixel compared
// bit-exactly with the golden model; the recorded intensities are then the device's S_j of the
// composition (primary: emission, ambient and Lambert diffuse on the host; secondary: the
// specular colour times the light colour times S_j, per light, saturated), and the image is
// compared with the same composition around the material's BRDF in double, in 8-bit sRGB codes.
// Images: <scene>_colour_rtl.png, <scene>_colour_reference.png, <scene>_colour_diff.png.
#pragma once

#include "compose.hpp"
#include "scene_stage.hpp"
#include "stream_harness.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace specular::sim {

struct ColourStats {
  std::string scene, config;
  uint64_t spans = 0, pixels = 0, mismatches = 0, protocol_errors = 0;
  ColourErrorStats err;  // the RTL's image against the reference, sRGB codes
  std::vector<std::string> images;
  double seconds = 0.0;
  bool ok() const { return pixels > 0 && mismatches == 0 && protocol_errors == 0; }
  nlohmann::json to_json() const;
};

void print_colour_table(const std::vector<ColourStats>& rows);

// The unit-intensity spans of a raster (tag: the span index cut to tag_mask).
std::vector<device::Span> unit_spans(const Raster& raster, const device::Format& f, uint64_t tag_mask);

// The composition around recorded intensities and its statistics (colour_stage.cpp).
ColourStats finish_colour(const LoadedScene& ls, const device::DeviceModel& dm, const std::vector<device::Span>& spans,
                          const StreamRun& run, const std::string& config, const std::string& images_dir);

template <class V>
ColourStats run_colour_scene(StreamHarness<V>& h, const LoadedScene& ls, const std::string& config,
                             const std::string& images_dir) {
  const std::vector<device::Span> spans = unit_spans(ls.raster, h.model().format(), h.tag_mask());
  uint64_t pixels = 0;
  for (const auto& s : spans) pixels += uint64_t{s.reg.len} + 1;
  StreamRun run;
  const uint64_t errors0 = h.counters().protocol_errors;
  h.run_back_to_back(spans, pixels, run);
  ColourStats st = finish_colour(ls, h.model(), spans, run, config, images_dir);
  st.protocol_errors = h.counters().protocol_errors - errors0;
  return st;
}

}  // namespace specular::sim
