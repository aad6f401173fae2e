// SPDX-License-Identifier: Apache-2.0
// Error of a phong_stream configuration (model/device/phong_error.hpp).
#include "phong_error.hpp"

#include "metrics.hpp"
#include "scanline_setup.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace specular::device {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

bool is_zero(const GeoVec& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double a) {
  return v * std::cos(a) + glm::cross(axis, v) * std::sin(a) + axis * glm::dot(axis, v) * (1.0 - std::cos(a));
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    const double l = glm::length(v);
    if (l > 1e-3) return v / l;
  }
}

glm::dvec3 perpendicular_unit(const glm::dvec3& v, std::mt19937_64& rng) {
  const glm::dvec3 r = random_unit(rng);
  return glm::normalize(glm::cross(v, r));
}

}  // namespace

double phong_exact(const GeoSpan& s, const PhongFormat& f, int i, double* cos_out) {
  const GeoFormat g = geo_format(f);
  if (cos_out) *cos_out = 0.0;
  const glm::dvec3 n1 = vec_value(s.n1, g), n2 = vec_value(s.n2, g), h1 = vec_value(s.h1, g);
  const glm::dvec3 he = f.const_h ? h1 : vec_value(s.he, g);
  if (is_zero(s.n1) || is_zero(s.n2) || is_zero(s.h1) || (!f.const_h && is_zero(s.he))) return 0.0;
  const double t = s.len > 0 ? static_cast<double>(i) / s.len : 0.0;
  const glm::dvec3 nn = n1 + (n2 - n1) * t, hh = h1 + (he - h1) * t;
  const double ln = glm::length(nn), lh = glm::length(hh);
  if (!(ln > 0.0) || !(lh > 0.0)) return 0.0;
  const double c = std::clamp(glm::dot(nn, hh) / (ln * lh), -1.0, 1.0);
  if (cos_out) *cos_out = c;
  if (s.n < 1 || s.n > static_cast<uint32_t>(kMaxN) || c <= 0.0) return 0.0;
  return std::ldexp(static_cast<double>(s.scale), -f.c_frac) * std::pow(c, static_cast<double>(s.n));
}

std::vector<GeoSpan> phong_sweep_spans(int n, const PhongFormat& f, uint64_t seed) {
  std::mt19937_64 rng(seed * 1000003ULL + static_cast<uint64_t>(n));
  const GeoFormat g = geo_format(f);
  const Format cf = c_format(f);
  const double xe = n > 1 ? epicenter_end(n) : kHalfPi;
  std::uniform_int_distribution<int> len(f.max_len() / 2 + 1, f.max_len());
  std::uniform_real_distribution<double> shrink(0.6, 1.0);
  std::vector<GeoSpan> spans;
  // l in the upper half of the counter (L = l, so |A| spans an octave of the normalization's
  // range), N and H shortened at random (a rasterizer's interpolated vectors are shorter than
  // 1): together they move |a|^2 |b|^2 over the rsqrt ROM's whole range [1, 4).
  auto add = [&](const glm::dvec3& n1, const glm::dvec3& n2, const glm::dvec3& h1, const glm::dvec3& he) {
    const double sn = shrink(rng), sh = shrink(rng);
    ScanlineInput in;
    in.n1 = sn * n1;
    in.n2 = sn * n2;
    in.h1 = sh * h1;
    in.he = f.const_h ? in.h1 : sh * he;
    in.n = n;
    in.l = len(rng);
    in.is = 1.0;
    spans.push_back(quantize_geo(in, g, cf, static_cast<uint32_t>(spans.size())));
  };
  for (int rep = 0; rep < 2; ++rep) {
    // Constant H: psi from just below 0 to just past the epicenter, then to past pi/2.
    {
      const glm::dvec3 h = random_unit(rng), u = perpendicular_unit(h, rng);
      add(rotate(h, u, -0.03 * xe), rotate(h, u, 1.05 * xe), h, h);
    }
    {
      const glm::dvec3 h = random_unit(rng), u = perpendicular_unit(h, rng);
      add(rotate(h, u, -0.02), rotate(h, u, std::min(kHalfPi + 0.1, 14.0 / std::sqrt(static_cast<double>(n)))), h, h);
    }
    if (rep == 0) {
      const glm::dvec3 h = random_unit(rng), u = perpendicular_unit(h, rng);
      add(rotate(h, u, -0.05), rotate(h, u, kHalfPi + 0.2), h, h);
    }
    {
      // The foot of the lobe, cos down to 0: where n = 1's relative budget meets the
      // output's LSB (the smallest pixels the relative budget covers, ref >= 4 LSB).
      const glm::dvec3 h = random_unit(rng), u = perpendicular_unit(h, rng);
      add(rotate(h, u, kHalfPi - 0.25), rotate(h, u, kHalfPi + 0.01), h, h);
    }
    // Varying H: N and H both turn, psi crosses the epicenter.
    {
      const glm::dvec3 h1 = random_unit(rng), u = perpendicular_unit(h1, rng), v = perpendicular_unit(h1, rng);
      const glm::dvec3 he = rotate(h1, v, 0.4);
      add(rotate(h1, u, -1.2 * xe), rotate(he, u, 1.2 * xe), h1, he);
    }
  }
  return spans;
}

PhongError phong_error_on(const PhongModel& m, int n, const std::vector<GeoSpan>& spans) {
  const PhongFormat& f = m.format();
  const GeoFormat g = geo_format(f);
  const Format cf = c_format(f);
  const double lsb = std::ldexp(1.0, -f.c_frac);
  const double xe = n > 1 ? epicenter_end(n) : kHalfPi;
  PhongError e;
  e.n = n;
  for (const GeoSpan& s : spans) {
    const double c_scale = std::ldexp(static_cast<double>(s.scale), -f.c_frac);
    const ScanlineInput in = geo_input(s, g, cf);
    for (int i = 0; i <= static_cast<int>(s.len); ++i) {
      double cosv = 0.0;
      const double ref = phong_exact(s, f, i, &cosv);
      const double truth = phong_truth(in, i);
      const double got = std::ldexp(static_cast<double>(m.pixel(s, i)), -f.c_frac);
      const double psi = std::acos(cosv);
      ++e.pixels;
      auto measure = [&](double r, double& rel_lsb, double& abs_lsb, bool raw) {
        const double err = std::abs(got - r);
        const double allow = std::max(0.0, err - lsb);
        if (c_scale > 0.0) abs_lsb = std::max(abs_lsb, allow / c_scale);
        if (raw && c_scale > 0.0) e.abs_raw = std::max(e.abs_raw, err / c_scale);
        if (cosv > 0.0 && psi <= xe && r >= 4 * lsb) {
          rel_lsb = std::max(rel_lsb, allow / r);
          if (raw && n > 1) e.rel_raw = std::max(e.rel_raw, err / r);
        }
      };
      if (cosv > 0.0 && psi <= xe) ++e.epicenter_pixels;
      measure(ref, e.rel_lsb, e.abs_lsb, true);
      measure(truth, e.rel_lsb_truth, e.abs_lsb_truth, false);
    }
  }
  return e;
}

PixelBudget PixelBudget::named(const std::string& name) {
  for (const PixelBudget& b : {b1(), b2(), b3(), b4()})
    if (name == b.name) return b;
  throw std::invalid_argument("error budget '" + name + "' is not one of b1, b2, b3, b4");
}

PhongError phong_error(const PhongModel& m, int n, uint64_t seed) {
  return phong_error_on(m, n, phong_sweep_spans(n, m.format(), seed));
}

}  // namespace specular::device
