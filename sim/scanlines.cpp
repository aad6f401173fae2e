// SPDX-License-Identifier: Apache-2.0
#include "scanlines.hpp"

#include "metrics.hpp"
#include "scanline_setup.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace specular::sim {
namespace {

constexpr double kPi = std::numbers::pi;

Scanline from_setup(const ScanlineInput& in, const device::Format& f, std::string kind) {
  const ScanlineSetup s = scanline_setup(in);
  Scanline sl;
  sl.kind = std::move(kind);
  const device::RegisterLoad load = device::load_registers(s, in.n, in.l, f);
  sl.reg = load.reg;
  sl.c_saturated = load.c_saturated;
  return sl;
}

// Planar geometry (N1 = N2 = z, halfway vectors in the xz plane): N1 . H(t) = cos(theta(t))
// with theta running from th1 to th2, so psi runs from th1 to th2 across the line.
ScanlineInput planar(double th1, double th2, double n, int l, double c) {
  ScanlineInput in;
  in.n1 = in.n2 = {0, 0, 1};
  in.h1 = {std::sin(th1), 0, std::cos(th1)};
  in.he = {std::sin(th2), 0, std::cos(th2)};
  in.is = 1.0;
  in.ks = c;
  in.n = n;
  in.l = l;
  return in;
}

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double ang) {
  const glm::dvec3 k = glm::normalize(axis);
  return v * std::cos(ang) + glm::cross(k, v) * std::sin(ang) + k * glm::dot(k, v) * (1 - std::cos(ang));
}

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    glm::dvec3 v{g(rng), g(rng), g(rng)};
    const double len = glm::length(v);
    if (len > 1e-6) return v / len;
  }
}

// A unit vector orthogonal to v, uniformly random in that circle.
glm::dvec3 random_perp(const glm::dvec3& v, std::mt19937_64& rng) {
  for (;;) {
    glm::dvec3 w = random_unit(rng);
    w -= v * glm::dot(v, w);
    const double len = glm::length(w);
    if (len > 1e-6) return w / len;
  }
}

}  // namespace

std::vector<Scanline> deterministic_scanlines(const device::Format& f) {
  std::vector<Scanline> out;
  const int max_len = f.max_len();
  const double full = 2.0;  // quantizes to the top code of register 1 (saturation, reported)
  const double c_levels[3] = {0.0, 1.0, full};
  const int short_l[5] = {0, 1, 2, 3, max_len};
  for (int n = 1; n <= f.max_n(); ++n) {
    const double xe = epicenter_end(n);
    // Span of about pi crossing 0 and one of +-pi/2 (alternating), full-scale C.
    const double off = 0.05 * (n % 7) / 7.0;
    if (n % 2 == 0)
      out.push_back(from_setup(planar(-1.75 + off, 1.35 + off, n, 255, full), f, "sweep-wide"));
    else
      out.push_back(from_setup(planar(1.75 - off, -1.35 - off, n, 255, full), f, "sweep-wide"));
    // Dense through the epicenter (peak inside the span), full-scale C.
    out.push_back(from_setup(planar(-1.2 * xe, 1.25 * xe, n, 127, full), f, "sweep-epicenter"));
    // Every l in {0,1,2,3,max}, C rotating through 0 / mid / full.
    for (int j = 0; j < 5; ++j) {
      const int l = short_l[j];
      const double c = c_levels[(n + j) % 3];
      if (l == max_len)
        out.push_back(from_setup(planar(-kPi / 2 - 0.2 + 0.001 * n, kPi / 2 + 0.2, n, l, c), f, "sweep-l"));
      else
        out.push_back(from_setup(planar(-0.7 * xe, 0.9 * xe, n, l, c), f, "sweep-l"));
    }
  }

  // Hard cases of docs/scanline_setup.md#hard-cases, each at the decoder boundaries and the extremes of n and l.
  const double hard_n[] = {1, 2, 3, 6, 7, 1000};
  const int hard_l[] = {0, 3, max_len};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double n : hard_n) {
    for (int l : hard_l) {
      auto add = [&](ScanlineInput in, const std::string& what) {
        in.n = n;
        in.l = l;
        out.push_back(from_setup(in, f, "hard:" + what));
      };
      ScanlineInput base = planar(0.1, 0.1, n, l, 1.0);
      add(base, "gamma=0");
      for (double eps : {1e-12, 1e-9, 1e-6}) {
        ScanlineInput in = base;
        in.he = rotate(in.h1, {0, 1, 0}, eps);
        add(in, "gamma-tiny");
      }
      {
        ScanlineInput in = planar(1.75, 1.9, n, l, 1.0);  // cos t1 < 0 all along
        add(in, "cos-t1<0");
        in = planar(kPi / 2, kPi / 2 + 0.3, n, l, 1.0);   // cos t1 = 0
        add(in, "cos-t1=0");
      }
      {
        ScanlineInput in = planar(-0.3, 0.4, n, l, 1.0);
        in.n2 = {0, 0, -1};
        add(in, "N1=-N2");
        in.n2 = glm::normalize(glm::dvec3{0.3, 0.2, -1});
        add(in, "N1~-N2");
      }
      {
        ScanlineInput in = base;
        in.h1 = {0, 0, 0};
        add(in, "L=-V");
        in = base;
        in.n1 = {0, 0, 2.5};
        in.n2 = {0, 0, 2.5};
        add(in, "non-unit");
        in = base;
        in.n1 = {0, 0, 0};
        add(in, "zero-normal");
        in = base;
        in.he = {nan, 0, 1};
        add(in, "nan");
        in = planar(-0.4, 0.4, n, l, 1.0);
        add(in, "psi-crosses-0");
        in = planar(-2.0, 1.0, n, l, 1.0);
        add(in, "psi-past-pi/2");
        in = planar(0.2, -0.2, n, l, 1.5);
        in.h1 = glm::normalize(glm::dvec3{std::sin(0.2), 0.4, std::cos(0.2)});  // A < 1
        add(in, "off-plane");
      }
    }
  }

  // Raw register patterns the setup does not produce: invalid n, |psi| around pi/2 (every
  // code across the boundary, both signs: the one's complement magnitude), |psi| >= 8 rad,
  // extreme codes, accumulator range.
  const int64_t amax = (int64_t{1} << (f.angle_bits - 1)) - 1, amin = -(int64_t{1} << (f.angle_bits - 1));
  const uint32_t cmax = (1u << f.c_bits) - 1;
  auto raw = [&](uint32_t c, int64_t psi0, int64_t dpsi, uint32_t n, uint32_t len, const std::string& what) {
    Scanline sl;
    sl.reg = {c, dpsi, psi0, n, len};
    sl.kind = "raw:" + what;
    out.push_back(sl);
  };
  const int64_t small = int64_t{1} << (f.angle_frac - 8);
  for (uint32_t n : {0u, 1001u, 1023u}) raw(cmax, -small * 8, small / 16, n, 255, "invalid-n");
  for (uint32_t n : {1u, 2u, 5u, 7u, 100u, 1000u}) {
    raw(cmax, amax, amin, n, max_len, "psi0=max,dpsi=min");
    raw(cmax, amin, amax, n, max_len, "psi0=min,dpsi=max");
    raw(cmax, 0, amax, n, max_len, "acc-range+");
    raw(cmax, 0, amin, n, max_len, "acc-range-");
    raw(cmax, (int64_t{8} << f.angle_frac) - 64, 1, n, 255, "|psi|=8-boundary");
    raw(cmax, -(int64_t{8} << f.angle_frac) - 64, 1, n, 255, "|psi|=-8-boundary");
    raw(1, -small, 1, n, 255, "C=1lsb");
  }
  // Negative dpsi whose low half carries at every step (its two's complement low half is
  // nearly all ones): the setup never produces dpsi < 0, so only these lines check the carry
  // between register 8's halves (docs/device.md#fixed-point-contract) going downwards.
  for (uint32_t n : {2u, 7u, 100u}) {
    raw(cmax, int64_t{1} << (f.angle_frac - 1), -(int64_t{1} << (f.angle_frac - 20)), n, max_len,
        "negative-dpsi-carry");
    raw(cmax, (int64_t{3} << (f.angle_frac - 4)) + 12345, -(int64_t{1} << (f.angle_frac - 12)) - 77, n, max_len,
        "negative-dpsi-carry-across-0");
  }
  const int64_t hp = f.half_pi_code();
  for (uint32_t n : {1u, 2u, 3u, 4u, 6u, 9u, 13u, 15u, 100u}) {
    raw(cmax, hp - 128, 1, n, 255, "psi=+pi/2-boundary");
    raw(cmax, -hp + 128, -1, n, 255, "psi=-pi/2-boundary");
  }
  return out;
}

std::vector<Scanline> random_scanlines(const device::Format& f, uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int max_len = f.max_len();
  std::vector<Scanline> out;
  out.reserve(count);
  for (int i = 0; i < count; ++i) {
    ScanlineInput in;
    // n: half uniform, half log-uniform (the small exponents and decoder edges matter most).
    in.n = u01(rng) < 0.5 ? 1.0 + std::floor(u01(rng) * 1000.0)
                          : std::clamp(std::round(std::exp(u01(rng) * std::log(1000.0))), 1.0, 1000.0);
    // l: mostly short lines, some long, a few at the counter maximum.
    const double p = u01(rng);
    if (p < 0.80) in.l = static_cast<int>(u01(rng) * 16);
    else if (p < 0.95) in.l = 16 + static_cast<int>(u01(rng) * 240);
    else if (p < 0.99) in.l = 256 + static_cast<int>(u01(rng) * (max_len - 256));
    else in.l = max_len;
    in.n1 = random_unit(rng);
    in.n2 = u01(rng) < 0.05 ? random_unit(rng) : rotate(in.n1, random_perp(in.n1, rng), 0.6 * u01(rng));
    // H1 near N1 so that most lines carry some highlight; its spread scales with the lobe.
    const double lobe = std::max(epicenter_end(in.n), 0.02);
    const double tilt = u01(rng) < 0.7 ? 3.0 * lobe * u01(rng) : 1.8 * u01(rng);
    in.h1 = rotate(in.n1, random_perp(in.n1, rng), tilt);
    in.he = u01(rng) < 0.5 ? in.h1 : rotate(in.h1, random_perp(in.h1, rng), 0.5 * u01(rng));
    in.is = u01(rng);
    in.ks = u01(rng) < 0.05 ? 2.0 + u01(rng) : 2.0 * u01(rng);
    out.push_back(from_setup(in, f, "random"));
  }
  return out;
}

}  // namespace specular::sim
