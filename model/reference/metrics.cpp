// SPDX-License-Identifier: Apache-2.0
#include "metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace specular {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Golden-section search for a maximum of g on [lo, hi].
double golden_max(const std::function<double(double)>& g, double lo, double hi, double* x_at) {
  const double r = 0.6180339887498949;
  double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
  double f1 = g(x1), f2 = g(x2);
  const double tol = 1e-13 * std::max(1.0, std::abs(hi));
  for (int it = 0; it < 200 && hi - lo > tol; ++it) {
    if (f1 < f2) {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + r * (hi - lo);
      f2 = g(x2);
    } else {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - r * (hi - lo);
      f1 = g(x1);
    }
  }
  // Compare with the bracket ends: the peak may sit on an end of the bracket.
  double best = f1, xb = x1;
  if (f2 > best) best = f2, xb = x2;
  const double fl = g(lo), fh = g(hi);
  if (fl > best) best = fl, xb = lo;
  if (fh > best) best = fh, xb = hi;
  if (x_at) *x_at = xb;
  return best;
}

// Gauss-Kronrod 7/15 nodes and weights on [-1, 1].
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

void gk15(const std::function<double(double)>& g, double a, double b, double& kr, double& err) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = g(c);
  double sk = fc * kWgk[7], sg = fc * kWg[3];
  for (int j = 0; j < 7; ++j) {
    const double dx = h * kXgk[j];
    const double f = g(c - dx) + g(c + dx);
    sk += kWgk[j] * f;
    if (j % 2 == 1) sg += kWg[j / 2] * f;
  }
  kr = sk * h;
  err = std::abs((sk - sg) * h);
}

double adapt(const std::function<double(double)>& g, double a, double b, double whole, double kr,
             double err, double rel_tol, double abs_tol, int depth) {
  if (err <= std::max(abs_tol, rel_tol * std::abs(whole)) || depth > 60 || b - a < 1e-15 * std::abs(b))
    return kr;
  const double m = 0.5 * (a + b);
  double k1, e1, k2, e2;
  gk15(g, a, m, k1, e1);
  gk15(g, m, b, k2, e2);
  // Each half gets half the absolute budget; `whole` keeps the relative target global.
  return adapt(g, a, m, whole, k1, e1, rel_tol, 0.5 * abs_tol, depth + 1) +
         adapt(g, m, b, whole, k2, e2, rel_tol, 0.5 * abs_tol, depth + 1);
}
}  // namespace

double epicenter_end(double n) {
  if (!(n > 1.0)) return kHalfPi;
  return std::atan(1.0 / std::sqrt(n - 1.0));
}

double maximize(const std::function<double(double)>& g, double lo, double hi, int samples, double* x_at) {
  samples = std::max(samples, 3);
  std::vector<double> xs(samples), vs(samples);
  for (int i = 0; i < samples; ++i) {
    xs[i] = lo + (hi - lo) * i / (samples - 1);
    vs[i] = g(xs[i]);
  }
  // Local maxima of the samples, best first; refine the leading few (the true peak can
  // hide next to a sample that is not the largest one).
  std::vector<int> peaks;
  for (int i = 0; i < samples; ++i) {
    const bool left = i == 0 || vs[i] >= vs[i - 1];
    const bool right = i == samples - 1 || vs[i] >= vs[i + 1];
    if (left && right) peaks.push_back(i);
  }
  std::sort(peaks.begin(), peaks.end(), [&](int p, int q) { return vs[p] > vs[q]; });
  int best_i = static_cast<int>(std::max_element(vs.begin(), vs.end()) - vs.begin());
  double best = vs[best_i], xb = xs[best_i];
  if (std::isinf(best) && best > 0) {
    if (x_at) *x_at = xb;
    return best;
  }
  const int refine = std::min<int>(static_cast<int>(peaks.size()), 4);
  for (int p = 0; p < refine; ++p) {
    const int i = peaks[p];
    const double a = xs[std::max(i - 1, 0)], b = xs[std::min(i + 1, samples - 1)];
    double xr;
    const double v = golden_max(g, a, b, &xr);
    if (v > best) best = v, xb = xr;
  }
  if (x_at) *x_at = xb;
  return best;
}

double max_rel_epicenter(const ShapeFn& f, double n, double* x_at) {
  const double xe = epicenter_end(n);
  auto rel = [&](double x) {
    if (x >= kHalfPi - 1e-12) {
      // n = 1 only: cos is 0 here up to rounding; the relative error is the limit,
      // 0 when F vanishes as well and unbounded when it does not.
      const double fx = f(x);
      return std::abs(fx) < 1e-12 ? 0.0 : kInf;
    }
    const double ref = std::pow(std::cos(x), n);
    return std::abs(f(x) - ref) / ref;
  };
  return maximize(rel, 0.0, xe, 257, x_at);
}

double max_abs_lobe(const ShapeFn& f, double n, double* x_at) {
  auto ab = [&](double x) { return std::abs(f(x) - (x >= kHalfPi ? 0.0 : std::pow(std::cos(x), n))); };
  // The lobe of cos^n is ~1/sqrt(n) wide: sample it densely, and the whole range coarsely
  // (slow tails such as Schlick's peak far out).
  double x1, x2;
  const double lobe = std::min(kHalfPi, 12.0 / std::sqrt(std::max(n, 1.0)));
  double v1 = maximize(ab, 0.0, lobe, 513, &x1);
  double v2 = lobe < kHalfPi ? maximize(ab, 0.0, kHalfPi, 513, &x2) : -1.0;
  if (v2 > v1) v1 = v2, x1 = x2;
  if (x_at) *x_at = x1;
  return v1;
}

ShapeError shape_error(const ShapeFn& f, double n) {
  ShapeError e;
  e.max_rel_epicenter = max_rel_epicenter(f, n, &e.x_at_max_rel);
  e.max_abs_lobe = max_abs_lobe(f, n, &e.x_at_max_abs);
  return e;
}

double integrate(const std::function<double(double)>& g, double a, double b, double rel_tol, double abs_tol) {
  double kr, err;
  gk15(g, a, b, kr, err);
  return adapt(g, a, b, kr, kr, err, rel_tol, abs_tol, 0);
}

double albedo(const ShapeFn& f, Convention conv, double lobe_n) {
  const double scale = conv == Convention::phong ? 1.0 : 0.5;
  auto g = [&](double t) { return f(scale * t) * std::cos(t) * std::sin(t); };
  // Breakpoints at multiples of the lobe width, so a narrow lobe is never missed by the
  // first coarse rule; the global relative target is set by the first pass over each piece.
  std::vector<double> br{0.0};
  if (lobe_n > 1.0) {
    const double w = 1.0 / (scale * std::sqrt(lobe_n));
    for (double m : {0.5, 1.0, 2.0, 4.0, 8.0})
      if (m * w < kHalfPi) br.push_back(m * w);
  }
  br.push_back(kHalfPi);
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < br.size(); ++i) total += integrate(g, br[i], br[i + 1], 1e-12, 1e-16);
  return 2.0 * 3.14159265358979323846 * total;
}

}  // namespace specular
