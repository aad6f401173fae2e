// SPDX-License-Identifier: Apache-2.0
// Decoder table (patent block 10) and the coefficient policies of ROM 9, docs/device.md.
//
// The device approximates cos^n(x) by cos^k(a x). The decoder picks k from n; the
// coefficient policy picks a:
//   maclaurin  a = sqrt(n/k)          (the patent: equal x^2 terms of the two series)
//   minimax    the a minimizing the max relative epicenter error (docs/metrics.md),
//              solved numerically and deterministically, converged to 1e-9 relative
//   kutlog:Q   a = acos(Q^(1/k)) / acos(Q^(1/n))   (the 2023 paper: exact at level Q)
#pragma once

#include <string>

namespace specular {

// Patent table: n=1 -> 1, 2 -> 2, 3..6 -> 4, 7..1000 -> 16; 0 for n < 1 or n > 1000.
// (Erratum: n up to 1000 needs 10 decoder inputs; the patent draws 9.)
int decoder_k(int n);
// Same table for a real exponent: bank j serves bank_max[j-1] < n <= bank_max[j].
int decoder_k_real(double n);

enum class CoefPolicy { maclaurin, minimax, kutlog };

struct CoefSpec {
  CoefPolicy policy = CoefPolicy::maclaurin;
  double Q = 0.5;  // kutlog only: the level in (0, 1) where cos^k(a x) equals cos^n(x)
};

// The a of cos^k(a x) for exponent n >= 1 and bank k >= 1.
// Throws std::invalid_argument for n < 1, k < 1, or (kutlog) Q outside (0, 1).
double coefficient(double n, int k, const CoefSpec& spec);

double coef_maclaurin(double n, int k);
double coef_kutlog(double n, int k, double Q);
double coef_minimax(double n, int k);

// "maclaurin", "minimax", "kutlog:0.3" (and "kutlog", meaning Q = 0.5).
// Throws std::invalid_argument with a message naming the accepted forms.
CoefSpec parse_coef_spec(const std::string& text);
std::string to_string(const CoefSpec& spec);

}  // namespace specular
