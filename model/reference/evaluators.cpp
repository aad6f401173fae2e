// SPDX-License-Identifier: Apache-2.0
#include "evaluators.hpp"

#include "metrics.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace specular {

namespace {
constexpr double kHalfPiE = 1.57079632679489661923;
constexpr double kLn2 = 0.693147180559945309417;
constexpr double kTwoOverLn2 = 2.0 / kLn2;
constexpr double kMinNormal = std::numeric_limits<double>::min();
constexpr uint64_t kMantMask = (uint64_t{1} << 52) - 1;
}  // namespace

double PowEval::operator()(double c) const { return c > 0.0 ? std::pow(c, n) : 0.0; }

double log2_poly(double c) {
  // Branch-free split c = 2^e * m with m in [sqrt(1/2), sqrt(2)): subtracting the bit
  // pattern of sqrt(1/2) moves the exponent boundary there (a data-dependent branch here
  // mispredicts half the time along a scanline).
  constexpr uint64_t kSqrtHalfBits = 0x3FE6A09E667F3BCDull;
  const uint64_t ix = std::bit_cast<uint64_t>(c) - kSqrtHalfBits;
  const int e = static_cast<int>(static_cast<int64_t>(ix) >> 52);  // c = 2^e * m
  const double m = std::bit_cast<double>((ix & kMantMask) + kSqrtHalfBits);
  // log2 m = 2/ln2 * atanh(t), atanh(t) = t + t^3/3 + t^5/5 + ...; the omitted tail,
  // 2/ln2 * t^11/11 / (1 - t^2) with |t| <= 0.1716, is below 1.1e-9.
  const double t = (m - 1.0) / (m + 1.0);
  const double t2 = t * t;
  const double s =
      t * (1.0 + t2 * (1.0 / 3 + t2 * (1.0 / 5 + t2 * (1.0 / 7 + t2 * (1.0 / 9)))));
  return e + kTwoOverLn2 * s;
}

double exp2_poly(double y) {
  if (!(y >= -1022.0)) return 0.0;  // also NaN -> 0
  if (y > 1023.0) return std::numeric_limits<double>::infinity();
  // Round to nearest with the 1.5 * 2^52 trick (no libm call, no branch).
  constexpr double kRound = 6755399441055744.0;
  const double i = (y + kRound) - kRound;
  const double g = (y - i) * kLn2;  // |g| <= ln2/2
  // exp(g) by Taylor to degree 7: the remainder is below e^|g| g^8/8! < 7.5e-9 relative.
  const double p = 1.0 + g * (1.0 + g * (1.0 / 2 + g * (1.0 / 6 + g * (1.0 / 24 + g * (1.0 / 120 +
                   g * (1.0 / 720 + g * (1.0 / 5040)))))));
  const double scale = std::bit_cast<double>(static_cast<uint64_t>(static_cast<int64_t>(i) + 1023) << 52);
  return p * scale;
}

double Exp2PolyEval::operator()(double c) const {
  if (!(c >= kMinNormal)) return 0.0;  // c <= 0, NaN, or subnormal (c^n is negligible)
  if (c >= 1.0) return 1.0;
  return exp2_poly(n * log2_poly(c));
}

LutEval::LutEval(double n_) : n(n_) {
  for (int i = 0; i < kEntries; ++i) table[i] = std::pow(static_cast<double>(i) / (kEntries - 1), n);
}

double LutEval::operator()(double c) const {
  if (!(c > 0.0)) return 0.0;
  if (c >= 1.0) return table[kEntries - 1];
  const double u = c * (kEntries - 1);
  const int i = std::min(static_cast<int>(u), kEntries - 2);  // c * 255 may round up to 255
  const double f = u - i;
  return table[i] + f * (table[i + 1] - table[i]);
}

double SchlickEval::operator()(double c) const { return c > 0.0 ? c / (n - n * c + c) : 0.0; }

double SchlickModEval::operator()(double c) const {
  if (!(c > 0.0)) return 0.0;
  const double u = n * (1.0 - c);
  return c / (0.5 * u * u + u + c);
}

LyonEval::LyonEval(double n, int w_) : n_over_m(n / std::ldexp(1.0, w_)), w(w_) {
  if (w_ < 0 || w_ > 10) throw std::invalid_argument("LyonEval: w must be in 0..10");
}

double LyonEval::operator()(double c) const {
  if (!(c > 0.0)) return 0.0;
  double b = n_over_m * (c - 1.0) + 1.0;
  if (b <= 0.0) return 0.0;
  for (int j = 0; j < w; ++j) b *= b;
  return b;
}

CoskEval::CoskEval(int k_, double a_) : k(k_), a(a_), cut(kHalfPiE / a_) {
  if (k_ < 1) throw std::invalid_argument("CoskEval: k must be >= 1");
  if (!(a_ > 0.0) || !std::isfinite(a_)) throw std::invalid_argument("CoskEval: a must be positive and finite");
}

double CoskEval::operator()(double x) const {
  x = std::abs(x);
  if (!(x < cut)) return 0.0;
  const double v = std::cos(a * x);
  // Square-and-multiply; for k = 2^j this is j squarings and no multiply.
  double r = 1.0, b = v;
  for (int e = k;;) {
    if (e & 1) r *= b;
    e >>= 1;
    if (!e) break;
    b *= b;
  }
  return r;
}

CoskEval patent_eval(int n, const CoefSpec& spec) {
  const int k = decoder_k(n);
  if (k == 0) throw std::invalid_argument("patent_eval: n must be in 1.." + std::to_string(kMaxN));
  return CoskEval(k, coefficient(n, k, spec));
}

CoskEval prototype_eval(double n) { return CoskEval(2, std::sqrt(n / 2.0)); }

}  // namespace specular
