// SPDX-License-Identifier: Apache-2.0
// Colour stage of the regression (docs/colour.md): every scene composed in colour by the RGB
// core. Each span of each light goes through specular_stream with Channels = 3 (the default
// widths) carrying its specular colour: C_ch = round(u c_ch), u the span's unit C code
// (Is = ks = norm = 1, so C = A^n) and c_ch = specular_ch E_j g (compose.hpp
// span_specular_colour), clamped to register 1 (counted); every pixel of every channel is
// compared with DeviceModel::rgb_pixel. The returned channels are the specular term of the
// composition (primary: emission, ambient and Lambert diffuse on the host; the lights' specular
// terms summed and saturated), compared with the same composition around the material's BRDF in
// double, in 8-bit sRGB codes. Images: <scene>_colour_rtl.png, <scene>_colour_reference.png,
// <scene>_colour_diff.png.
#pragma once

#include "compose.hpp"
#include "scene_stage.hpp"
#include "clocking.hpp"
#include "verilated_model.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace specular::sim {

struct ColourStats {
  std::string scene, config;
  uint64_t spans = 0, pixels = 0, mismatches = 0, protocol_errors = 0;
  uint64_t saturated_spans = 0;  // a channel's C clamped to register 1's largest code
  ColourErrorStats err;  // the RTL's image against the reference, sRGB codes
  // The RTL's image against the same composition around C_ch cos^n(psi_i) of its own registers in
  // double: the device's error alone (what its budget bounds), without the setup's.
  ColourErrorStats device_err;
  std::vector<std::string> images;
  double seconds = 0.0;
  bool ok() const { return pixels > 0 && mismatches == 0 && protocol_errors == 0; }
  nlohmann::json to_json() const;
};

void print_colour_table(const std::vector<ColourStats>& rows);

// One span of the RGB core: the registers (reg.c unused) and a C per channel.
struct RgbSpan {
  device::Span span;
  device::RgbC c{};
};

// The spans of a raster with their colour C (tag: the span index cut to tag_mask).
std::vector<RgbSpan> rgb_spans(const LoadedScene& ls, const device::Format& f, uint64_t tag_mask, uint64_t& saturated);

// What the core returned, in stream order: each pixel's channels, last flag and tag.
struct RgbRun {
  std::vector<device::RgbC> px;
  std::vector<uint8_t> last;
  std::vector<uint32_t> tag;
  uint64_t protocol_errors = 0;
};

// The composition around the returned channels and its statistics (colour_stage.cpp).
ColourStats finish_colour(const LoadedScene& ls, const device::DeviceModel& dm, const std::vector<RgbSpan>& spans,
                          const RgbRun& run, const std::string& config, const std::string& images_dir);

// The spans back to back through a verilated specular_stream with Channels = 3, px_ready_i high.
template <class V>
ColourStats run_colour_scene(const LoadedScene& ls, const device::DeviceModel& dm, const std::string& config,
                             const std::string& images_dir) {
  VerilatedModel<V> vm("specular_stream_rgb");
  V& top = *vm.top();
  top.span_valid_i = 0;
  top.px_ready_i = 1;
  vm.power_up();
  reset(top);
  uint64_t saturated = 0;
  const uint64_t tag_mask = (uint64_t{1} << 16) - 1;
  const std::vector<RgbSpan> spans = rgb_spans(ls, dm.format(), tag_mask, saturated);
  uint64_t total = 0;
  for (const auto& s : spans) total += uint64_t{s.span.reg.len} + 1;
  RgbRun run;
  run.px.reserve(total);
  const int cb = dm.format().c_bits;
  const uint64_t cmask = (uint64_t{1} << cb) - 1;
  size_t next = 0;
  // Every span and pixel in order; a stall of the output (px_ready_i is high) or a lost pixel
  // ends the run at the limit.
  for (uint64_t cycle = 0, limit = 2 * total + 1000; run.px.size() < total && cycle < limit; ++cycle) {
    if (next < spans.size()) {
      const RgbSpan& s = spans[next];
      top.span_valid_i = 1;
      top.span_c_i = (uint64_t{s.c[0]} & cmask) | ((uint64_t{s.c[1]} & cmask) << cb) | ((uint64_t{s.c[2]} & cmask) << (2 * cb));
      top.span_psi0_i = static_cast<uint32_t>(s.span.reg.psi0);
      top.span_dpsi_i = static_cast<uint32_t>(s.span.reg.dpsi);
      top.span_n_i = s.span.reg.n;
      top.span_len_i = s.span.reg.len;
      top.span_tag_i = s.span.tag;
    } else {
      top.span_valid_i = 0;
    }
    top.eval();
    const bool accepted = top.span_valid_i && top.span_ready_o;
    if (top.px_valid_o) {
      const uint64_t w = top.px_intensity_o;
      run.px.push_back({static_cast<uint32_t>(w & cmask), static_cast<uint32_t>((w >> cb) & cmask),
                        static_cast<uint32_t>((w >> (2 * cb)) & cmask)});
      run.last.push_back(top.px_last_o);
      run.tag.push_back(top.px_tag_o);
    }
    tick(top);
    if (accepted) ++next;
  }
  if (run.px.size() != total || next != spans.size()) ++run.protocol_errors;
  ColourStats st = finish_colour(ls, dm, spans, run, config, images_dir);
  st.saturated_spans = saturated;
  return st;
}

}  // namespace specular::sim
