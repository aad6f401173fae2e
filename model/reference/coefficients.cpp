// SPDX-License-Identifier: Apache-2.0
#include "coefficients.hpp"

#include "metrics.hpp"
#include "number_text.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace specular {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kNegInf = -std::numeric_limits<double>::infinity();

void check_nk(double n, int k) {
  if (!(n >= 1.0) || !std::isfinite(n))
    throw std::invalid_argument("coefficient: n must be a finite number >= 1");
  if (k < 1) throw std::invalid_argument("coefficient: k must be >= 1");
}

// Extremes of r(x) = k ln cos(a x) - n ln cos(x) over [0, xe]; F/cos^n = exp(r).
// r'(x) = n tan x - k a tan(a x) = tan x * (n - k a * tan(a x)/tan x), and
// tan(a x)/tan x is monotone on the interval (increasing for a > 1, decreasing for
// a < 1: sin(a y) <= a sin(y) because sin(y)/y decreases on (0, pi)). So r has at most
// one interior critical point, and its extremes are at 0, xe and that point. This is
// what makes the minimax solve cheap and deterministic.
struct RRange {
  double rmax, rmin;
};

RRange r_range(double n, int k, double a, double xe) {
  auto r = [&](double x) {
    const double ca = std::cos(a * x);
    if (a * x >= kHalfPi || ca <= 0.0) return kNegInf;  // F = 0 past the cut
    return k * std::log(ca) - n * std::log(std::cos(x));
  };
  auto h = [&](double x) {  // sign of r'
    if (a * x >= kHalfPi) return kNegInf;
    return n * std::tan(x) - k * a * std::tan(a * x);
  };
  double rmax = 0.0, rmin = 0.0;  // r(0) = 0
  double end = xe;
  if (a * xe >= kHalfPi) {
    rmin = kNegInf;  // F reaches 0 inside the epicenter: relative error 1
    end = kHalfPi / a;
  } else {
    const double re = r(xe);
    rmax = std::max(rmax, re);
    rmin = std::min(rmin, re);
  }
  const double s0 = n - k * a * a;  // sign of r' near 0
  const double se = h(end * (1.0 - 1e-12));
  if ((s0 > 0.0 && se < 0.0) || (s0 < 0.0 && se > 0.0)) {
    double lo = 0.0, hi = end;  // h(lo) has the sign of s0
    for (int it = 0; it < 200 && hi - lo > 1e-15 * end; ++it) {
      const double mid = 0.5 * (lo + hi);
      const double hm = h(mid);
      if ((hm > 0.0) == (s0 > 0.0))
        lo = mid;
      else
        hi = mid;
    }
    const double rc = r(0.5 * (lo + hi));
    rmax = std::max(rmax, rc);
    rmin = std::min(rmin, rc);
  }
  return {rmax, rmin};
}
}  // namespace

int decoder_k(int n) { return decoder_k_real(n); }

int decoder_k_real(double n) {
  const int j = decoder_bank(kPatentBankMaxN, n);
  return j < 0 ? 0 : kPatentBanks[static_cast<std::size_t>(j)];
}

std::vector<int> patent_bank_edges() {
  std::vector<int> edges;
  int first = 1;
  for (const int last : kPatentBankMaxN) {
    if (edges.empty() || edges.back() != first) edges.push_back(first);
    if (edges.back() != last) edges.push_back(last);
    first = last + 1;
  }
  return edges;
}

double coef_maclaurin(double n, int k) {
  check_nk(n, k);
  return std::sqrt(n / k);
}

double coef_kutlog(double n, int k, double Q) {
  check_nk(n, k);
  if (!(Q > 0.0 && Q < 1.0)) throw std::invalid_argument("coefficient: kutlog Q must be in (0, 1)");
  return std::acos(std::pow(Q, 1.0 / k)) / std::acos(std::pow(Q, 1.0 / n));
}

double coef_minimax(double n, int k) {
  check_nk(n, k);
  if (n == static_cast<double>(k)) return 1.0;  // cos^k(x) is exact: zero error
  const double xe = epicenter_end(n);
  // P(a) = max positive relative error (non-increasing in a, since r decreases in a),
  // M(a) = max negative relative error (non-decreasing). The max of the two is minimal
  // where they cross: bisection on g = P - M is monotone and deterministic.
  auto g = [&](double a) {
    const RRange rr = r_range(n, k, a, xe);
    const double P = std::expm1(rr.rmax);
    const double M = (rr.rmin == kNegInf) ? 1.0 : -std::expm1(rr.rmin);
    return P - M;
  };
  const double a0 = std::sqrt(n / k);
  double lo = a0, hi = a0;
  if (g(a0) < 0.0) {  // F too low: optimum has a smaller a
    double step = 0.02;
    do {
      hi = lo;
      lo = a0 * (1.0 - step);
      step = std::min(2.0 * step, 0.999);
    } while (g(lo) < 0.0 && step < 0.999);
  } else {
    double step = 0.02;
    do {
      lo = hi;
      hi = a0 * (1.0 + step);
      step *= 2.0;
    } while (g(hi) > 0.0 && step < 1e6);
  }
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (g(mid) > 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

double coefficient(double n, int k, const CoefSpec& spec) {
  switch (spec.policy) {
    case CoefPolicy::maclaurin: return coef_maclaurin(n, k);
    case CoefPolicy::minimax: return coef_minimax(n, k);
    case CoefPolicy::kutlog: return coef_kutlog(n, k, spec.Q);
  }
  throw std::invalid_argument("coefficient: unknown policy");
}

CoefSpec parse_coef_spec(const std::string& text) {
  const std::string usage = "expected maclaurin, minimax or kutlog:Q with Q in (0, 1)";
  if (text == "maclaurin") return {CoefPolicy::maclaurin, 0.5};
  if (text == "minimax") return {CoefPolicy::minimax, 0.5};
  if (text == "kutlog") return {CoefPolicy::kutlog, 0.5};
  if (text.rfind("kutlog:", 0) == 0) {
    const std::optional<double> Q = whole_double(text.substr(7));
    if (!Q || !(*Q > 0.0 && *Q < 1.0)) throw std::invalid_argument("coefficient policy '" + text + "': " + usage);
    return {CoefPolicy::kutlog, *Q};
  }
  throw std::invalid_argument("coefficient policy '" + text + "': " + usage);
}

std::string to_string(const CoefSpec& spec) {
  switch (spec.policy) {
    case CoefPolicy::maclaurin: return "maclaurin";
    case CoefPolicy::minimax: return "minimax";
    case CoefPolicy::kutlog: {
      std::ostringstream s;
      s << "kutlog:" << spec.Q;
      return s.str();
    }
  }
  return "?";
}

}  // namespace specular
