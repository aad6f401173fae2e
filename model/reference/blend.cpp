// SPDX-License-Identifier: Apache-2.0
// The two-bank blend and its minimax fit (model/reference/blend.hpp, docs/display_exact.md).
#include "blend.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace specular {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;

double term(int k, double a, double x) {
  const double z = a * x;
  return z < kHalfPi ? std::pow(std::cos(z), k) : 0.0;
}

std::string set_text(const std::vector<int>& banks) {
  std::string s;
  for (int k : banks) s += (s.empty() ? "{" : ", ") + std::to_string(k);
  return s + "}";
}

// The sampled lobe of one n: abscissae and cos^n.
struct Lobe {
  std::vector<double> x, g;
};

Lobe lobe(int n, int samples) {
  Lobe l;
  const double end = std::min(kHalfPi, std::sqrt(40.0 / n));
  l.x.resize(samples);
  l.g.resize(samples);
  for (int i = 0; i < samples; ++i) {
    l.x[i] = end * i / (samples - 1);
    l.g[i] = std::pow(std::cos(l.x[i]), n);
  }
  return l;
}

// For fixed a1, a2: the t in [0, 1] minimizing max |r_i + t s_i| (convex in t), and that maximum.
double best_t(const Lobe& l, int k1, double a1, int k2, double a2, double& t_out) {
  const size_t m = l.x.size();
  std::vector<double> r(m), s(m);
  for (size_t i = 0; i < m; ++i) {
    const double f1 = term(k1, a1, l.x[i]), f2 = term(k2, a2, l.x[i]);
    r[i] = f1 - l.g[i];
    s[i] = f2 - f1;
  }
  auto worst = [&](double t) {
    double w = 0.0;
    for (size_t i = 0; i < m; ++i) w = std::max(w, std::abs(r[i] + t * s[i]));
    return w;
  };
  constexpr double kInvPhi = 0.6180339887498949;
  double lo = 0.0, hi = 1.0;
  double c = hi - kInvPhi * (hi - lo), d = lo + kInvPhi * (hi - lo);
  double fc = worst(c), fd = worst(d);
  for (int it = 0; it < 60; ++it) {
    if (fc <= fd) {
      hi = d;
      d = c;
      fd = fc;
      c = hi - kInvPhi * (hi - lo);
      fc = worst(c);
    } else {
      lo = c;
      c = d;
      fc = fd;
      d = lo + kInvPhi * (hi - lo);
      fd = worst(d);
    }
  }
  t_out = 0.5 * (lo + hi);
  return worst(t_out);
}

}  // namespace

double blend_value(const BlendCoef& c, double x) {
  x = std::abs(x);
  return (1.0 - c.t) * term(c.k1, c.a1, x) + c.t * term(c.k2, c.a2, x);
}

void blend_banks(const std::vector<int>& banks, int n, int& k1, int& k2) {
  for (size_t j = 0; j < banks.size(); ++j)
    if (banks[j] < 1 || (j > 0 && banks[j] <= banks[j - 1]))
      throw std::invalid_argument("blend bank set " + set_text(banks) + " must be strictly increasing from >= 1");
  const auto it = std::upper_bound(banks.begin(), banks.end(), n);
  if (it == banks.begin())
    throw std::invalid_argument("blend: no bank of " + set_text(banks) + " is <= n = " + std::to_string(n));
  k1 = *(it - 1);
  k2 = it == banks.end() ? k1 : *it;
}

BlendCoef blend_maclaurin(int n, int k1, int k2) {
  BlendCoef c{n, k1, k2, std::sqrt(static_cast<double>(n) / k1), std::sqrt(static_cast<double>(n) / k2), 0.0, 0.0};
  if (k2 != k1) c.t = (1.0 / k1 - 1.0 / n) / (1.0 / k1 - 1.0 / k2);
  return c;
}

BlendCoef blend_minimax(int n, int k1, int k2, int samples) {
  if (n < 1 || n > 1000) throw std::invalid_argument("blend_minimax: n = " + std::to_string(n) + " is not in 1..1000");
  if (k1 < 1 || k1 > n || (k2 <= n && k2 != k1))
    throw std::invalid_argument("blend_minimax: banks k1 = " + std::to_string(k1) + ", k2 = " + std::to_string(k2) +
                                " do not serve n = " + std::to_string(n) + " (need k1 <= n < k2, or k2 = k1 <= n)");
  if (samples < 16) throw std::invalid_argument("blend_minimax: samples must be >= 16");
  BlendCoef c = blend_maclaurin(n, k1, k2);
  if (k1 == n) {  // cos^n itself: exact
    c.t = 0.0;
    c.a1 = 1.0;
    return c;
  }
  const Lobe l = lobe(n, samples);
  auto f = [&](const std::array<double, 2>& p, double& t) {
    return best_t(l, k1, std::exp(p[0]), k2, std::exp(p[1]), t);
  };
  std::array<double, 2> best{std::log(c.a1), std::log(c.a2)};
  double t_best = c.t;
  double f_best = f(best, t_best);
  // Nelder-Mead on (ln a1, ln a2), restarted from the best point with a fresh simplex until a
  // restart gains less than 1e-6 of the error.
  double step = 0.03;
  for (int restart = 0; restart < 8; ++restart) {
    std::array<std::array<double, 2>, 3> v{best, best, best};
    v[1][0] += step;
    v[2][1] += step;
    std::array<double, 3> fv{};
    std::array<double, 3> tv{};
    for (int i = 0; i < 3; ++i) fv[i] = f(v[i], tv[i]);
    for (int it = 0; it < 300; ++it) {
      std::array<int, 3> o{0, 1, 2};
      std::sort(o.begin(), o.end(), [&](int a, int b) { return fv[a] < fv[b]; });
      const int b = o[0], m = o[1], w = o[2];
      if (std::abs(v[w][0] - v[b][0]) + std::abs(v[w][1] - v[b][1]) < 1e-11) break;
      const std::array<double, 2> cen{0.5 * (v[b][0] + v[m][0]), 0.5 * (v[b][1] + v[m][1])};
      auto at = [&](double s) {
        return std::array<double, 2>{cen[0] + s * (v[w][0] - cen[0]), cen[1] + s * (v[w][1] - cen[1])};
      };
      double tr = 0.0;
      const auto xr = at(-1.0);
      const double fr = f(xr, tr);
      if (fr < fv[b]) {
        double te = 0.0;
        const auto xe = at(-2.0);
        const double fe = f(xe, te);
        if (fe < fr) {
          v[w] = xe, fv[w] = fe, tv[w] = te;
        } else {
          v[w] = xr, fv[w] = fr, tv[w] = tr;
        }
      } else if (fr < fv[m]) {
        v[w] = xr, fv[w] = fr, tv[w] = tr;
      } else {
        double tc = 0.0;
        const auto xc = fr < fv[w] ? at(-0.5) : at(0.5);
        const double fc = f(xc, tc);
        if (fc < std::min(fr, fv[w])) {
          v[w] = xc, fv[w] = fc, tv[w] = tc;
        } else {  // shrink towards the best vertex
          for (int i : {m, w}) {
            v[i] = {v[b][0] + 0.5 * (v[i][0] - v[b][0]), v[b][1] + 0.5 * (v[i][1] - v[b][1])};
            fv[i] = f(v[i], tv[i]);
          }
        }
      }
    }
    const int b = static_cast<int>(std::min_element(fv.begin(), fv.end()) - fv.begin());
    const bool gained = fv[b] < f_best * (1.0 - 1e-6);
    if (fv[b] < f_best) {
      best = v[b];
      f_best = fv[b];
      t_best = tv[b];
    }
    if (!gained && restart > 0) break;
    step *= 0.3;
  }
  c.a1 = std::exp(best[0]);
  c.a2 = std::exp(best[1]);
  c.t = t_best;
  // The error at these coefficients, on a grid four times denser than the fit's.
  const Lobe fine = lobe(n, 4 * samples);
  c.max_abs = 0.0;
  for (size_t i = 0; i < fine.x.size(); ++i)
    c.max_abs = std::max(c.max_abs, std::abs(blend_value(c, fine.x[i]) - fine.g[i]));
  return c;
}

std::vector<BlendCoef> blend_minimax_table(const std::vector<int>& banks, int n_max) {
  // The bank pairs first (blend_banks validates the set and throws on this thread), then the fits,
  // each n independent of the others: one thread per core, each taking every T-th n, so the table
  // is the same whatever the thread count (about 20 s for 1000 n on one core).
  std::vector<BlendCoef> out(static_cast<size_t>(std::max(n_max, 0)));
  for (int n = 1; n <= n_max; ++n) blend_banks(banks, n, out[n - 1].k1, out[n - 1].k2);
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1U, 16U);
  std::vector<std::exception_ptr> errors(threads);
  auto work = [&](unsigned id) {
    try {
      // No bank above n (k2 = k1): the last bank read twice, at two angles.
      for (int n = 1 + static_cast<int>(id); n <= n_max; n += static_cast<int>(threads))
        out[n - 1] = blend_minimax(n, out[n - 1].k1, out[n - 1].k2);
    } catch (...) {
      errors[id] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned id = 1; id < threads; ++id) pool.emplace_back(work, id);
  work(0);
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace specular
