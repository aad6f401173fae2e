// SPDX-License-Identifier: Apache-2.0
// The two-bank blend of docs/display_exact.md: cos^n(x) approximated by
//   B(x) = (1 - t) cos^k1(a1 x) + t cos^k2(a2 x),   k1 <= n < k2 (each term 0 where a x >= pi/2),
// whose weight t cancels the leading term of the two banks' errors (about (n^2/k - n) x^4 / 12 in
// the exponent, of opposite signs for k1 < n and k2 > n), and its minimax coefficients per n.
#pragma once

#include <vector>

namespace specular {

// The coefficients of one n: banks k1 < k2 (k2 = k1 where n is itself a bank: t = 0), the angle
// factors a1, a2, the weight t of bank k2 in [0, 1], and max_abs = max over x in [0, pi/2] of
// |B(x) - cos^n(x)| as the fit measured it (a fraction of C).
struct BlendCoef {
  int n = 1, k1 = 1, k2 = 1;
  double a1 = 1.0, a2 = 1.0, t = 0.0;
  double max_abs = 0.0;
};

// B(x) in double for |x| <= pi/2.
double blend_value(const BlendCoef& c, double x);

// The pair of banks that serves n: k1 the largest bank <= n, k2 the next bank (k1 when there is
// none). Throws std::invalid_argument (naming n and the bank set) when no bank is <= n or the
// set is not strictly increasing from >= 1.
void blend_banks(const std::vector<int>& banks, int n, int& k1, int& k2);

// The starting point of the fit (docs/display_exact.md#coefficients): maclaurin a = sqrt(n/k)
// for each bank and the weight that cancels the x^4 terms, t = (1/k1 - 1/n) / (1/k1 - 1/k2).
BlendCoef blend_maclaurin(int n, int k1, int k2);

// The minimax fit (docs/display_exact.md#coefficients): (a1, a2, t) minimizing the maximum
// absolute error over the lobe. For fixed (a1, a2) the error is affine in t, so the best t is a
// one-dimensional convex problem (golden section); (ln a1, ln a2) by Nelder-Mead from
// blend_maclaurin, restarted until it no longer improves. The error is sampled at `samples`
// points over [0, min(pi/2, sqrt(40/n))] (past it every term is below e^-20). n = k1 gives the
// exact t = 0, a1 = 1; k2 = k1 < n (no bank above n) reads the one bank at two angles.
// Deterministic. Throws std::invalid_argument for n < 1, n > 1000 or
// k1 > n, k2 <= n (unless k2 = k1).
BlendCoef blend_minimax(int n, int k1, int k2, int samples = 600);

// The fits of every n in 1..n_max for a bank set (index n - 1).
std::vector<BlendCoef> blend_minimax_table(const std::vector<int>& banks, int n_max);

}  // namespace specular
