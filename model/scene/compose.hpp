// SPDX-License-Identifier: Apache-2.0
// Colour images on the host: the scene's colours (scenes/README.md#colour) composed in linear
// light around the device's specular intensity, then sRGB-encoded to 8 bits.
//
// Per covered pixel, with N = pixel_normal() (the rasterizer's interpolated normal), L_j the
// direction to light j at the pixel's surface point, E_j = Light::colour() and every product
// of colours taken channel by channel:
//   primary   = emission + ambient * diffuse + sum_j diffuse * E_j * max(N.L_j, 0)    (Lambert)
//   secondary = min(1, sum_j specular_colour * E_j * g * S_j)                     per channel
//   image     = clamp(primary + secondary, 0, 1)
// g = specular_gain(material): the material's `norm` times the BRDF's normalization when the
// material names a normalized one. S_j is the unit specular intensity of light j at the
// pixel, from one pass of spans per light (the rasterizer emits one span per visible run and
// light): the device's output for the span's registers with C = 1 (device_unit_specular: what
// the hardware returns) or, for the reference, the material's BRDF shape at the true angle
// between N and H (reference_unit_specular). Device and reference share everything else.
#pragma once

#include "device_model.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "scene.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace specular {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<glm::dvec3> value;  // linear light, row-major, y downwards
  std::vector<uint8_t> covered;   // 1 where some span wrote the pixel

  RgbImage() = default;
  RgbImage(int w, int h);
  glm::dvec3& at(int x, int y) { return value[static_cast<size_t>(y) * width + x]; }
  const glm::dvec3& at(int x, int y) const { return value[static_cast<size_t>(y) * width + x]; }
};

struct ColourLayers {
  RgbImage primary;    // emission, ambient and Lambert diffuse (not clamped)
  RgbImage secondary;  // specular, every channel saturated at 1
  RgbImage image;      // primary + secondary clamped to [0, 1]: what is encoded
};

// The factor g of the specular term: Material::norm, times ModelEvaluator::own_norm() of the
// BRDF when Material::brdf is a normalized one.
double specular_gain(const Material& m);

// S for the device: golden_evaluator (image.hpp) on the span with Is = ks = s(n) = 1, so that
// the setup's C is A^n <= 1 alone (the interpolation's amplitude, scanline_setup.hpp) and the
// device returns its C cos^k(a psi_i), its approximation of (N.H)^n.
Evaluator device_unit_specular(const device::DeviceModel& dm);
// S for the reference, in double: the material's BRDF shape (brdf.hpp) at
// x = acos(N.H), N = pixel_normal(), H the true halfway vector at the pixel (halfway()); 0 where
// N is undefined. For blinn_phong this is pixel_truth() / (Is ks s(n)).
Evaluator reference_unit_specular(const Scene& scene);

// The composition above over every span of `raster` (made from `scene`).
ColourLayers compose(const Scene& scene, const Raster& raster, const Evaluator& unit_specular);

// The same with the specular term coloured elsewhere (an RGB core multiplies the colour in):
// `specular(s, out)` writes each pixel's specular_colour(s) * S of span s, summed over the lights
// and saturated here as above; span_specular_colour is the factor specular E_j g of span s.
using SpecularEvaluator = std::function<void(const Span& span, std::span<glm::dvec3> out)>;
ColourLayers compose_specular(const Scene& scene, const Raster& raster, const SpecularEvaluator& specular);
glm::dvec3 span_specular_colour(const Scene& scene, const Span& s);

// The sRGB transfer function of IEC 61966-2-1, on [0, 1] (arguments are clamped to it):
//   encode(v) = 12.92 v for v <= 0.0031308, 1.055 v^(1/2.4) - 0.055 above;
//   decode(e) = e / 12.92 for e <= 0.04045, ((e + 0.055) / 1.055)^2.4 above.
double srgb_encode(double linear);
double srgb_decode(double encoded);
// The 8-bit code of a linear value: round(255 encode(clamp(v, 0, 1))).
uint8_t srgb_code(double linear);

// Difference of two colour images in 8-bit sRGB codes, over the pixels covered in either.
struct ColourErrorStats {
  std::array<int, 3> max_abs{};      // per channel r, g, b: worst |a - b| in codes
  std::array<double, 3> mean_abs{};  // mean |a - b| in codes
  // Worst |clamp(a) - clamp(b)| in linear value, clamped to [0, 1] as the codes are: a fraction of
  // full scale (an 8-bit display's half step is 2^-9 of it).
  std::array<double, 3> max_linear{};
  std::array<int, 2> argmax{-1, -1};  // x, y of the worst pixel over the three channels
  size_t pixels = 0;
};
ColourErrorStats srgb_code_error(const RgbImage& a, const RgbImage& b);

// 8-bit sRGB PNG of the image (every pixel, covered or not: an uncovered one holds 0, black).
// Throws std::runtime_error naming the path when the file cannot be written.
void write_srgb_png(const std::string& path, const RgbImage& img);
// The difference a - b in 8-bit sRGB codes, per channel, amplified: 128 + gain (a - b) with the
// largest integer gain that keeps the worst difference R within [1, 255] (gain 1 when R is 0 or
// above 127); pixels covered by neither are black. Below the image a strip with `label`, the
// gain, and a grey bar from -R to +R labelled with R in codes.
void write_code_diff_png(const std::string& path, const RgbImage& a, const RgbImage& b, const std::string& label);

}  // namespace specular
