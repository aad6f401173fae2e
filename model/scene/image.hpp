// SPDX-License-Identifier: Apache-2.0
// Image accumulation from spans, per-pixel evaluators, PNG output and error heatmaps.
//
// Typical use (and how a device image is added: one more Evaluator):
//   Raster r = rasterize(scene);
//   Image phong = render(r, phong_evaluator(scene));
//   Image flt   = render(r, float_model_evaluator());
//   Image rtl   = render(r, [&](const Span& s, std::span<double> out) { /* drive the RTL */ });
//   write_heatmap_png("x_device_error.png", difference(rtl, flt), "RTL - FLOAT");
#pragma once

#include "device_model.hpp"
#include "raster.hpp"
#include "setup_batch.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace specular {

struct Image {
  int width = 0, height = 0;
  std::vector<double> value;     // row-major, y downwards
  std::vector<uint8_t> covered;  // 1 where some span wrote the pixel

  Image() = default;
  Image(int w, int h);
  double& at(int x, int y) { return value[static_cast<size_t>(y) * width + x]; }
  double at(int x, int y) const { return value[static_cast<size_t>(y) * width + x]; }
  bool is_covered(int x, int y) const { return covered[static_cast<size_t>(y) * width + x] != 0; }
};

// Fills out[i] (i = 0..l, out.size() == l + 1) with the intensity of pixel x_start + i.
using Evaluator = std::function<void(const Span& span, std::span<double> out)>;

// Evaluates every span once and ADDS its values into the image (lights sum).
Image render(const Raster& raster, const Evaluator& evaluator);

// Per-pixel Phong truth (raster.hpp: pixel_truth).
Evaluator phong_evaluator(const Scene& scene);
// Spherical-interpolation float model: scanline_setup(span.setup_in), then
// C cos^n(psi_i), 0 where |psi_i| >= pi/2.
Evaluator float_model_evaluator();

// Bit-accurate golden model of the device: DeviceModel::line(host::span_registers(span.setup_in)),
// converted back to intensities. The RTL evaluator is the same with the Verilator
// model in place of DeviceModel::line.
Evaluator golden_evaluator(const device::DeviceModel& dm);

// a - b where either is covered (uncovered counts as 0), covered = a or b.
Image difference(const Image& a, const Image& b);

struct ImageErrorStats {
  double max_abs = 0.0;
  double rms = 0.0;
  int argmax_x = -1, argmax_y = -1;
  size_t pixels = 0;  // covered pixels
};
ImageErrorStats error_stats(const Image& err);

// 8-bit grey PNG of clamp(value * scale, 0, 1); uncovered pixels dark blue-grey.
// Throws std::runtime_error naming the path when the file cannot be written.
void write_png(const std::string& path, const Image& img, double scale = 1.0);

// Diverging heatmap (blue negative, white 0, red positive) over the symmetric range
// [-R, R], R = `range` or max |err| when range <= 0; below the image a strip with
// `label`, the colour bar and its numeric range (-R, 0, +R) in a built-in bitmap font.
void write_heatmap_png(const std::string& path, const Image& err, const std::string& label, double range = 0.0);

// An RGB PNG of w x h pixels (3 bytes a pixel, row-major). Throws std::runtime_error naming the
// path when the file cannot be written.
void write_rgb_png(const std::string& path, int w, int h, const std::vector<uint8_t>& rgb);

// The legend strip under a difference image (write_heatmap_png; compose.hpp's
// write_code_diff_png): legend_height(w) rows that draw_legend fills from row `top` of the
// w-wide buffer `rgb` (background first): `title` (`short_title` when it does not fit), a bar
// from -1 to +1 coloured by bar(u), and the labels lo, 0 and hi under its ends and its middle.
int legend_height(int w);
void draw_legend(std::vector<uint8_t>& rgb, int w, int top, const std::array<uint8_t, 3>& background,
                 const std::string& title, const std::string& short_title,
                 const std::function<std::array<uint8_t, 3>(double)>& bar, const std::string& lo,
                 const std::string& hi);

// Text rendering with the built-in 5x7 font (digits, A-Z, a few signs; lower case
// drawn as upper case). Exposed for tests and other tools. RGB buffer, stride = 3*w.
void draw_text(std::vector<uint8_t>& rgb, int w, int h, int x, int y, const std::string& text, int scale,
               const std::array<uint8_t, 3>& colour);
int text_width(const std::string& text, int scale);
// True when the font has a glyph for c (upper-cased).
bool font_has_glyph(char c);

}  // namespace specular
