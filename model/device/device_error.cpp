// SPDX-License-Identifier: Apache-2.0
// Device error sweeps (model/device/device_error.hpp).
#include "device_error.hpp"

#include "metrics.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace specular {

namespace {
constexpr double kHalfPiE = 1.57079632679489661923;
}  // namespace

int srgb8_code(double v) {
  v = std::clamp(v, 0.0, 1.0);
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255.0 * e));
}

DeviceLine make_device_line(const device::Format& f, int n, double end, int l) {
  DeviceLine d;
  d.regs.c = device::quantize_c(1.0, f);
  d.regs.psi0 = 0;
  d.regs.dpsi = l > 0 ? device::quantize_angle(end / l, f) : 0;
  d.regs.n = static_cast<uint32_t>(n);
  d.regs.len = static_cast<uint32_t>(l);
  d.dpsi = device::angle_value(d.regs.dpsi, f);
  d.c = device::c_value(d.regs.c, f);
  return d;
}

DeviceError device_error(const device::DeviceModel& dm, int n) {
  const device::Format& f = dm.format();
  const int len = f.max_len();  // counter 5's longest line
  DeviceError err;
  // n = 1: the epicenter would reach pi/2 where cos^n -> 0 and any fixed-point output has
  // unbounded relative error; stop at cos = 1/2 (the level where n = 2's epicenter ends).
  const double xe = n > 1 ? epicenter_end(n) : std::acos(0.5);
  const double lsb = std::ldexp(1.0, -f.c_frac);
  const double xe_lsb = n > 1 ? epicenter_end(n) : kHalfPiE;
  enum class Kind { rel, rel_lsb, abs };
  auto sweep = [&](double end, Kind kind) {
    const DeviceLine d = make_device_line(f, n, end, len);
    const std::vector<uint32_t> out = dm.line(d.regs);
    for (int i = 0; i <= len; ++i) {
      const double psi = i * d.dpsi;  // exact: the accumulator adds integers
      if (psi >= kHalfPiE) break;
      const double ref = d.c * std::pow(std::cos(psi), n);
      const double got = device::c_value(out[i], f);
      const double e = std::abs(got - ref);
      if (kind == Kind::rel) {
        if (psi <= xe) err.max_rel_epicenter = std::max(err.max_rel_epicenter, e / ref);
      } else if (kind == Kind::rel_lsb) {
        if (psi <= xe_lsb && ref >= 4 * lsb)
          err.max_rel_epicenter_lsb = std::max(err.max_rel_epicenter_lsb, std::max(0.0, e - lsb) / ref);
      } else {
        err.max_abs_lobe = std::max(err.max_abs_lobe, e);
        err.max_srgb8_codes = std::max(err.max_srgb8_codes, std::abs(srgb8_code(got) - srgb8_code(ref)));
      }
    }
  };
  sweep(xe, Kind::rel);
  sweep(xe_lsb, Kind::rel_lsb);
  sweep(std::min(kHalfPiE, 12.0 / std::sqrt(static_cast<double>(n))), Kind::abs);
  sweep(kHalfPiE, Kind::abs);
  return err;
}

DenseError dense_abs_error(const device::DeviceModel& dm, int n, int64_t step_codes) {
  const device::Format& f = dm.format();
  DenseError e;
  device::Registers r;
  r.c = static_cast<uint32_t>(1) << f.c_frac;  // C = 1
  r.n = static_cast<uint32_t>(n);
  r.len = static_cast<uint32_t>(f.max_len());
  r.dpsi = std::max<int64_t>(step_codes, 1);
  const double lsb = std::ldexp(1.0, -f.c_frac), half_pi = std::acos(-1.0) / 2;
  const double end = std::min(half_pi, std::sqrt(40.0 / n));
  const double end_code = std::ldexp(end, f.angle_frac);
  for (int64_t p0 = 0; static_cast<double>(p0) < end_code; p0 += r.dpsi * (r.len + 1)) {
    r.psi0 = p0;
    const std::vector<uint32_t> line = dm.line(r);
    for (size_t i = 0; i < line.size(); ++i) {
      const double psi = std::ldexp(static_cast<double>(p0 + static_cast<int64_t>(i) * r.dpsi), -f.angle_frac);
      const double ref = psi < half_pi ? std::pow(std::cos(psi), n) : 0.0;
      const double err = std::fabs(line[i] * lsb - ref);
      ++e.pixels;
      if (err > e.max_abs) e.max_abs = err, e.psi = psi;
    }
  }
  return e;
}

}  // namespace specular
