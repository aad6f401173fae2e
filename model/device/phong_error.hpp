// SPDX-License-Identifier: Apache-2.0
// The error of a phong_stream configuration, measured on its golden model with the device's
// budget and metrics (docs/metrics.md, docs/phong_hw.md#error-measurement): the relative error
// in the epicenter with a 1-output-LSB allowance and the absolute error over the lobe, per n.
#pragma once

#include "phong_model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular::device {

// Per-pixel Blinn-Phong of a span in double, from the exact values of its codes:
//   N_i = N1 + (N2 - N1) i / l, H_i = H1 + (He - H1) i / l (He = H1 when f.const_h),
//   c = N_i . H_i / (|N_i| |H_i|), I = scale * max(0, c)^n (0 for n = 0 or n > 1000).
// `cos_out` (optional) receives c (0 for a zero vector). Written from the interface's
// definition (docs/interfaces.md#geometry-span-interface), no code shared with PhongModel.
double phong_exact(const GeoSpan& s, const PhongFormat& f, int i, double* cos_out = nullptr);

// The spans that measure exponent n: nine long spans (l in 1024..2047) whose true angle psi
// (acos c) sweeps the epicenter densely, the whole lobe to past pi/2, the foot of the lobe
// (psi from pi/2 - 0.25 to past pi/2), and the epicenter with a varying H, in frames rotated
// at random (seeded), with N and H shortened at random to 0.6..1, C = 1.
std::vector<GeoSpan> phong_sweep_spans(int n, const PhongFormat& f, uint64_t seed);

// An error budget of docs/metrics.md#budgets: B1 (the device's default: 0.10 % of the pixel + 1
// LSB in the epicenter, 0.01 C + 1 LSB over the lobe), B2 (an 8-bit display: every pixel within
// 2^-9 of full scale, C), B3 (the patent's claim: 1 % + 1 LSB, 0.01 C + 1 LSB), B4 (a 10-bit
// display: every pixel within 2^-11 C; docs/display_exact.md). The budget a
// build configuration of the device is regressed against is rom_image.hpp's ErrorBudget.
struct PixelBudget {
  const char* name = "b1";
  double rel_lsb = 1e-3;   // bound of PhongError::rel_lsb
  double abs_lsb = 1e-2;   // bound of PhongError::abs_lsb
  double abs_raw = 1e300;  // bound of PhongError::abs_raw
  static PixelBudget b1() { return {}; }
  static PixelBudget b2() { return {"b2", 1e300, 1e300, 1.0 / 512.0}; }
  static PixelBudget b3() { return {"b3", 1e-2, 1e-2, 1e300}; }
  static PixelBudget b4() { return {"b4", 1e300, 1e300, 1.0 / 2048.0}; }
  // b1, b2, b3 or b4; throws std::invalid_argument naming the allowed names otherwise.
  static PixelBudget named(const std::string& name);
};

struct PhongError {
  int n = 0;
  // max (|err| - 1 LSB)^+ / ref over the epicenter psi <= x_e(n) where ref >= 4 LSB
  // (n = 1: psi <= pi/2), as device_error's max_rel_epicenter_lsb; the budget is 0.10 %.
  double rel_lsb = 0.0;
  double rel_raw = 0.0;  // max |err| / ref over the epicenter (n > 1), no allowance
  // max (|err| - 1 LSB)^+ / C over every pixel (the lobe and past it); the budget is 0.01.
  double abs_lsb = 0.0;
  // The same two against phong_truth (model/setup/scanline_setup.hpp), which normalizes
  // N1, N2, H1, He before interpolating: it differs from phong_exact by the rounding of the
  // end vectors' lengths to the interface.
  double rel_lsb_truth = 0.0;
  double abs_lsb_truth = 0.0;
  double abs_raw = 0.0;  // max |err| / C over every pixel, no allowance (budget B2)
  int64_t pixels = 0, epicenter_pixels = 0;
  bool meets(double rel_budget = 1e-3, double abs_budget = 1e-2) const {
    return rel_lsb <= rel_budget && abs_lsb <= abs_budget;
  }
  // The budget, each bound scaled by margin (<= 1: held to a fraction of it).
  bool meets(const PixelBudget& b, double margin = 1.0) const {
    return rel_lsb <= b.rel_lsb * margin && abs_lsb <= b.abs_lsb * margin && abs_raw <= b.abs_raw * margin;
  }
};

// The error of a configuration at exponent n over `spans` (phong_sweep_spans by default).
PhongError phong_error(const PhongModel& m, int n, uint64_t seed = 1);
PhongError phong_error_on(const PhongModel& m, int n, const std::vector<GeoSpan>& spans);

}  // namespace specular::device
