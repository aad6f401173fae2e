// SPDX-License-Identifier: Apache-2.0
#include "brdf.hpp"

#include "metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace specular {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
}

double blinn(double x, double n) {
  // Cut at x = pi/2 exactly like the ROM's a x >= pi/2 test, so that cos^k(1 x) and cos^n
  // agree bit for bit when k = n (cos of the double nearest pi/2 is 6e-17, not 0).
  if (std::abs(x) >= kHalfPi) return 0.0;
  const double c = std::cos(x);
  return c > 0.0 ? std::pow(c, n) : 0.0;
}

double phong(double x, double n) { return blinn(x, n); }

double cosk_shape(double x, int k, double a) {
  // ROM 12 holds cos^k on [0, pi/2) only; negative angles use |zeta| (cos is even).
  const double z = a * std::abs(x);
  if (z >= kHalfPi) return 0.0;
  return std::pow(std::cos(z), k);
}

double patent_shape(double x, int k, double a) { return cosk_shape(x, k, a); }

double patent(double x, int n, const CoefSpec& spec) {
  const int k = decoder_k(n);
  if (k == 0) return 0.0;  // the device outputs 0 for n outside 1..1000
  return cosk_shape(x, k, coefficient(n, k, spec));
}

double prototype(double x, double n) { return cosk_shape(x, 2, std::sqrt(n / 2.0)); }

double schlick(double c, double n) {
  if (c <= 0.0) return 0.0;
  return c / (n - n * c + c);
}

double schlick_mod(double c, double n) {
  if (c <= 0.0) return 0.0;
  const double u = n * (1.0 - c);
  return c / (0.5 * u * u + n - n * c + c);
}

double lyon(double c, double n, int m) {
  if (c <= 0.0) return 0.0;
  const double b = (n / m) * (c - 1.0) + 1.0;
  return b > 0.0 ? std::pow(b, m) : 0.0;
}

double kutlog_shape(double x, double n, int k, double Q) { return cosk_shape(x, k, coef_kutlog(n, k, Q)); }

double f16(double c, double n) { return f16_norm(n) * lyon(c, n, 16); }

double blinn_phong_norm(double n) { return (n + 8.0) / (8.0 * kPi); }
double phong_norm(double n) { return (n + 2.0) / (2.0 * kPi); }
double f16_norm(double n) { return (n + 6.0) / 24.55; }

double kutlog_coef_exact(double n, int k, double Q) {
  const double a = coef_kutlog(n, k, Q);
  // The phong-convention albedo of the shape is 2 pi Int (the integrand is zero past
  // gran = pi/(2a) because the shape is).
  const double alb = albedo([&](double x) { return cosk_shape(x, k, a); }, Convention::phong, n);
  return 1.0 / alb;
}

double kutlog_coef_fit(double n, int k, double Q) {
  if (Q >= 0.1 && Q <= 0.4) return 0.608 * n * (Q - 0.193) / (2.0 * Q + 2.0 * k) + 0.161 * n + 0.284;
  if (Q >= 0.5 && Q <= 0.9) return 0.743 * Q * (-0.0133 * k * n + 0.167 * n) / k + 0.167 * n + 0.245;
  throw std::invalid_argument("kutlog_coef_fit: Q must be in [0.1, 0.4] or [0.5, 0.9] (the fits' ranges)");
}

double kutlog_fit_error(int k, double Q, int* n_at) {
  double worst = -1.0;
  int at = 0;
  for (int n = k + 1; n <= kMaxN; ++n) {
    // coef_fit * 2 pi Int = coef_fit / coef_exact
    const double e = std::abs(kutlog_coef_fit(n, k, Q) / kutlog_coef_exact(n, k, Q) - 1.0);
    if (e > worst) worst = e, at = n;
  }
  if (n_at) *n_at = at;
  return worst;
}

const std::vector<std::string>& model_names() {
  static const std::vector<std::string> names{"blinn", "patent", "prototype", "schlick",
                                              "schlick-mod", "lyon", "f16", "kutlog"};
  return names;
}

std::optional<Model> parse_model(const std::string& s) {
  if (s == "blinn") return Model::blinn;
  if (s == "phong") return Model::phong;
  if (s == "patent") return Model::patent;
  if (s == "prototype") return Model::prototype;
  if (s == "schlick") return Model::schlick;
  if (s == "schlick-mod") return Model::schlick_mod;
  if (s == "lyon") return Model::lyon;
  if (s == "f16") return Model::f16;
  if (s == "kutlog") return Model::kutlog;
  return std::nullopt;
}

std::string model_name(Model m) {
  switch (m) {
    case Model::blinn: return "blinn";
    case Model::phong: return "phong";
    case Model::patent: return "patent";
    case Model::prototype: return "prototype";
    case Model::schlick: return "schlick";
    case Model::schlick_mod: return "schlick-mod";
    case Model::lyon: return "lyon";
    case Model::f16: return "f16";
    case Model::kutlog: return "kutlog";
  }
  return "?";
}

ModelEvaluator make_evaluator(Model model, const ModelParams& p) {
  if (!(p.n >= 1.0) || !std::isfinite(p.n)) throw std::invalid_argument("model: n must be a finite number >= 1");
  ModelEvaluator e;
  e.model = model;
  e.n = p.n;
  e.Q = p.Q;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (model) {
    case Model::blinn:
    case Model::phong:
      e.k = 0;
      e.a = 1.0;
      break;
    case Model::patent:
      e.k = p.k > 0 ? p.k : decoder_k_real(p.n);
      if (e.k == 0) throw std::invalid_argument("model patent: n must be in [1, " + std::to_string(kMaxN) + "] for the decoder");
      e.a = coefficient(p.n, e.k, p.coef);
      break;
    case Model::prototype:
      e.k = 2;
      e.a = std::sqrt(p.n / 2.0);
      break;
    case Model::schlick:
    case Model::schlick_mod:
      e.k = 0;
      e.a = nan;
      break;
    case Model::lyon:
      if (p.m < 1) throw std::invalid_argument("model lyon: m must be >= 1");
      e.k = e.m = p.m;
      e.a = nan;
      break;
    case Model::f16:
      e.k = e.m = 16;
      e.a = nan;
      break;
    case Model::kutlog:
      if (p.k < 1) throw std::invalid_argument("model kutlog: k is required (>= 1)");
      e.k = p.k;
      e.a = coef_kutlog(p.n, p.k, p.Q);
      break;
  }
  return e;
}

double ModelEvaluator::shape(double x) const {
  // Past pi/2 the halfway vector is below the surface: every model is 0 there (the
  // cos^k(a x) family alone is only cut at a x = pi/2, which lies beyond pi/2 when a < 1).
  if (std::abs(x) >= kHalfPi) return 0.0;
  switch (model) {
    case Model::blinn:
    case Model::phong: return blinn(x, n);
    case Model::patent:
    case Model::prototype:
    case Model::kutlog: return cosk_shape(x, k, a);
    case Model::schlick: return schlick(std::cos(x), n);
    case Model::schlick_mod: return schlick_mod(std::cos(x), n);
    case Model::lyon:
    case Model::f16: return lyon(std::cos(x), n, m);
  }
  return 0.0;
}

double ModelEvaluator::own_norm() const {
  switch (model) {
    case Model::phong: return phong_norm(n);
    case Model::f16: return f16_norm(n);
    case Model::kutlog: return 1.0 / albedo([this](double x) { return shape(x); }, Convention::phong, n);
    default: return blinn_phong_norm(n);
  }
}

}  // namespace specular
