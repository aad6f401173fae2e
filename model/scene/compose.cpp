// SPDX-License-Identifier: Apache-2.0
// Colour composition, sRGB encoding and the colour images (compose.hpp).
#include "compose.hpp"

#include "brdf.hpp"


#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace specular {

using glm::dvec3;

RgbImage::RgbImage(int w, int h)
    : width(w), height(h), value(static_cast<size_t>(w) * h, dvec3(0.0)), covered(static_cast<size_t>(w) * h, 0) {}

double specular_gain(const Material& m) {
  if (!m.brdf.normalized) return m.norm;
  ModelParams p;
  p.n = m.n;
  return m.norm * make_evaluator(m.brdf.model, p).own_norm();
}

Evaluator device_unit_specular(const device::DeviceModel& dm) {
  return [golden = golden_evaluator(dm)](const Span& s, std::span<double> out) {
    Span unit = s;
    unit.setup_in.is = unit.setup_in.ks = unit.setup_in.norm = 1.0;
    golden(unit, out);
  };
}

Evaluator reference_unit_specular(const Scene& scene) {
  return [&scene](const Span& s, std::span<double> out) {
    ModelParams p;
    p.n = scene.materials[s.material].n;
    const ModelEvaluator brdf = make_evaluator(scene.materials[s.material].brdf.model, p);
    for (size_t i = 0; i < out.size(); ++i) {
      const int px = static_cast<int>(i);
      const dvec3 n = pixel_normal(s, px);
      if (n == dvec3(0.0)) {
        out[i] = 0.0;
        continue;
      }
      const double c = glm::dot(n, halfway(scene, s.light, span_point(s, px)));
      out[i] = brdf.shape(std::acos(std::clamp(c, -1.0, 1.0)));
    }
  };
}

dvec3 span_specular_colour(const Scene& scene, const Span& s) {
  const Material& m = scene.materials[s.material];
  return m.specular_colour() * scene.lights[s.light].colour() * specular_gain(m);
}

ColourLayers compose(const Scene& scene, const Raster& raster, const Evaluator& unit_specular) {
  std::vector<double> s_unit;
  return compose_specular(scene, raster, [&](const Span& s, std::span<dvec3> out) {
    s_unit.assign(out.size(), 0.0);
    unit_specular(s, std::span<double>(s_unit));
    const dvec3 specular = span_specular_colour(scene, s);
    for (size_t i = 0; i < out.size(); ++i) out[i] = specular * s_unit[i];
  });
}

ColourLayers compose_specular(const Scene& scene, const Raster& raster, const SpecularEvaluator& specular) {
  ColourLayers c{RgbImage(raster.width, raster.height), RgbImage(raster.width, raster.height),
                 RgbImage(raster.width, raster.height)};
  std::vector<dvec3> spec;
  for (const Span& s : raster.spans) {
    const Material& m = scene.materials[s.material];
    const Light& light = scene.lights[s.light];
    const dvec3 diffuse = m.diffuse * light.colour();
    // Every visible run has one span per light: its light-independent terms come with light 0.
    const dvec3 constant = s.light == 0 ? m.emission + scene.ambient * m.diffuse : dvec3(0.0);
    spec.assign(static_cast<size_t>(s.pixels()), dvec3(0.0));
    specular(s, std::span<dvec3>(spec));
    const size_t row = static_cast<size_t>(s.y) * raster.width + s.x_start;
    for (int i = 0; i < s.pixels(); ++i) {
      const dvec3 n = pixel_normal(s, i);
      const double n_l = n == dvec3(0.0) ? 0.0 : std::max(glm::dot(n, light.to_light(span_point(s, i))), 0.0);
      c.primary.value[row + i] += constant + diffuse * n_l;
      c.secondary.value[row + i] += spec[static_cast<size_t>(i)];
      c.primary.covered[row + i] = c.secondary.covered[row + i] = c.image.covered[row + i] = 1;
    }
  }
  for (size_t k = 0; k < c.image.value.size(); ++k) {
    c.secondary.value[k] = glm::min(c.secondary.value[k], dvec3(1.0));
    c.image.value[k] = glm::clamp(c.primary.value[k] + c.secondary.value[k], dvec3(0.0), dvec3(1.0));
  }
  return c;
}

double srgb_encode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double e) {
  e = std::clamp(e, 0.0, 1.0);
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

uint8_t srgb_code(double v) { return static_cast<uint8_t>(std::lround(255.0 * srgb_encode(v))); }

ColourErrorStats srgb_code_error(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("srgb_code_error: image sizes differ");
  ColourErrorStats st;
  std::array<double, 3> sum{};
  int worst = -1;
  for (size_t k = 0; k < a.value.size(); ++k) {
    if (!(a.covered[k] | b.covered[k])) continue;
    ++st.pixels;
    for (int ch = 0; ch < 3; ++ch) {
      const int d = std::abs(int(srgb_code(a.value[k][ch])) - int(srgb_code(b.value[k][ch])));
      const double lin = std::abs(std::clamp(a.value[k][ch], 0.0, 1.0) - std::clamp(b.value[k][ch], 0.0, 1.0));
      st.max_linear[ch] = std::max(st.max_linear[ch], lin);
      sum[ch] += d;
      st.max_abs[ch] = std::max(st.max_abs[ch], d);
      if (d > worst) {
        worst = d;
        st.argmax = {static_cast<int>(k % static_cast<size_t>(a.width)), static_cast<int>(k / static_cast<size_t>(a.width))};
      }
    }
  }
  for (int ch = 0; ch < 3; ++ch) st.mean_abs[ch] = st.pixels ? sum[ch] / static_cast<double>(st.pixels) : 0.0;
  return st;
}

void write_srgb_png(const std::string& path, const RgbImage& img) {
  std::vector<uint8_t> rgb(img.value.size() * 3);
  for (size_t k = 0; k < img.value.size(); ++k)
    for (int ch = 0; ch < 3; ++ch) rgb[3 * k + static_cast<size_t>(ch)] = srgb_code(img.value[k][ch]);
  write_rgb_png(path, img.width, img.height, rgb);
}

void write_code_diff_png(const std::string& path, const RgbImage& a, const RgbImage& b, const std::string& label) {
  const ColourErrorStats st = srgb_code_error(a, b);
  const int R = std::max({st.max_abs[0], st.max_abs[1], st.max_abs[2]});
  const int gain = R > 0 ? std::max(1, 127 / R) : 1;
  auto level = [gain](int d) { return static_cast<uint8_t>(std::clamp(128 + gain * d, 0, 255)); };

  const int W = a.width;
  const int H = a.height + legend_height(W);
  std::vector<uint8_t> rgb(static_cast<size_t>(W) * H * 3, 0);
  for (size_t k = 0; k < a.value.size(); ++k) {
    if (!(a.covered[k] | b.covered[k])) continue;  // black
    for (int ch = 0; ch < 3; ++ch)
      rgb[3 * k + static_cast<size_t>(ch)] =
          level(int(srgb_code(a.value[k][ch])) - int(srgb_code(b.value[k][ch])));
  }
  // Strip: label and gain, a grey bar from -R to +R, its range in codes.
  std::string lo = "0", hi = "0";
  if (R > 0) {
    lo = std::to_string(-R);
    hi = std::to_string(R);
    hi.insert(hi.begin(), '+');
  }
  draw_legend(rgb, W, a.height, {0, 0, 0}, label + ", SRGB CODES X" + std::to_string(gain),
              label + " X" + std::to_string(gain),
              [&](double u) {
                const uint8_t g = level(static_cast<int>(std::lround(u * R)));
                return std::array<uint8_t, 3>{g, g, g};
              },
              lo, hi);
  write_rgb_png(path, W, H, rgb);
}

}  // namespace specular
