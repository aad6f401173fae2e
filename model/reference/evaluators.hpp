// SPDX-License-Identifier: Apache-2.0
// Fast per-pixel evaluators of the specular term, the competitors of docs/speed_error.md.
//
// Each is a small value type built once per exponent n (per scanline, as a renderer would)
// and called per pixel with the input it naturally takes:
//   cosine input  c = N.H (a dot product the renderer already has):
//     PowEval, Exp2PolyEval, LutEval, SchlickEval, SchlickModEval, LyonEval
//   angle input   x (radians; what the spherical-interpolation accumulator produces):
//     CoskEval (the patent, its minimax variant, the prototype)
// Every evaluator approximates the shape cos^n(x), equal to 1 at x = 0 and 0 for c <= 0
// (x >= pi/2). None allocates or branches on n per pixel.
#pragma once

#include "coefficients.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace specular {

// Exact reference: std::pow(c, n), 0 for c <= 0.
struct PowEval {
  double n = 1.0;
  double operator()(double c) const;
};

// c^n = exp2(n * log2(c)) with our own polynomials, the way software rasterizers do it:
//   log2 c: the IEEE exponent plus log2 of the mantissa m in [sqrt(1/2), sqrt(2)) by the
//           odd series 2/ln2 * atanh(t), t = (m-1)/(m+1), |t| < 0.1716, terms up to t^9
//           (truncation error < 1.1e-9 absolute);
//   exp2 y: y = i + f, i = round(y), |f| <= 1/2, exp(f ln 2) by a degree-7 Taylor polynomial
//           (truncation error < 7.5e-9 relative), times 2^i assembled in the exponent field.
// The degrees are the smallest that keep c^n within 1e-6 relative up to n = 1000 (the log2
// error is multiplied by n ln 2). Results below 2^-1022 are flushed to 0 (no subnormals).
// Relative error against the exact c^n: below 1e-8 + 1e-9 * n for normal results.
struct Exp2PolyEval {
  double n = 1.0;
  double operator()(double c) const;
};
double log2_poly(double c);  // c > 0, finite, normal
double exp2_poly(double y);  // y <= 1023; 0 below -1022

// 256-entry table of c^n over c in [0, 1] (knots c_i = i/255), linear interpolation between
// knots; rebuilt per n. Exact (to rounding) at the knots.
struct LutEval {
  static constexpr int kEntries = 256;
  explicit LutEval(double n);
  double operator()(double c) const;
  double n;
  std::array<double, kEntries> table{};
};

struct SchlickEval {  // c / (n - n c + c)
  double n = 1.0;
  double operator()(double c) const;
};

struct SchlickModEval {  // c / (0.5 (n(1-c))^2 + n - n c + c)
  double n = 1.0;
  double operator()(double c) const;
};

// max(0, (n/m)(c - 1) + 1)^m with m = 2^w, computed by w squarings (lyon-16: 4 squarings).
struct LyonEval {
  explicit LyonEval(double n, int w = 4);
  double operator()(double c) const;
  double n_over_m;
  int w;
};

// cos^k(a x) for a|x| < pi/2, else 0: one cos, then k by repeated squaring (k = 1, 2, 4, 16
// take 0, 1, 2, 4 squarings; other k use square-and-multiply). Input: the angle x.
struct CoskEval {
  CoskEval(int k, double a);
  double operator()(double x) const;
  int k;
  double a;
  double cut;  // pi/2 / a
};
// The patent (decoder k, coefficient policy a), float.
CoskEval patent_eval(int n, const CoefSpec& spec = {});
// The prototype of Abbas, Szirmay-Kalos and Horvath: cos^2(a x), a = sqrt(n/2).
CoskEval prototype_eval(double n);


}  // namespace specular
