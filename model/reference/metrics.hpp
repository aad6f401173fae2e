// SPDX-License-Identifier: Apache-2.0
// Error metrics and albedo integrals of docs/metrics.md.
#pragma once

#include <functional>

namespace specular {

using ShapeFn = std::function<double(double)>;  // F(x), x = angle in radians

enum class Convention { phong, blinn };  // albedo angle = theta (phong) or theta/2 (blinn)

// End of the epicenter: the inflection of cos^n, atan(1/sqrt(n-1)) for n > 1, pi/2 for n <= 1.
double epicenter_end(double n);

struct ShapeError {
  double max_rel_epicenter = 0.0;  // max |F - cos^n| / cos^n over [0, x_e(n)] (fraction)
  double max_abs_lobe = 0.0;       // max |F - cos^n| over [0, pi/2]
  double x_at_max_rel = 0.0;
  double x_at_max_abs = 0.0;
};

// Dense sampling followed by golden-section refinement of every leading local maximum,
// so the figures are stable to far more than 3 significant digits. For n = 1 the epicenter
// reaches pi/2 where cos = 0: the relative error there is 0 when F vanishes too and
// +infinity when it does not (the sup is unbounded).
ShapeError shape_error(const ShapeFn& f, double n);
double max_rel_epicenter(const ShapeFn& f, double n, double* x_at = nullptr);
double max_abs_lobe(const ShapeFn& f, double n, double* x_at = nullptr);

// 2 pi integral_0^(pi/2) F(angle(theta)) cos(theta) sin(theta) d theta (adaptive Gauss-Kronrod,
// relative tolerance 1e-11). `lobe_n` (> 0) hints the lobe width ~ 1/sqrt(n) to place breakpoints.
double albedo(const ShapeFn& f, Convention conv, double lobe_n = 0.0);

// Adaptive Gauss-Kronrod (7/15) quadrature on [a, b].
double integrate(const std::function<double(double)>& g, double a, double b,
                 double rel_tol = 1e-11, double abs_tol = 1e-300);

// Maximum of g on [lo, hi]: evaluate on `samples` uniform points, then golden-section
// refine the best local maxima. Returns the value; *x_at gets the argument.
double maximize(const std::function<double(double)>& g, double lo, double hi, int samples,
                double* x_at = nullptr);

}  // namespace specular
