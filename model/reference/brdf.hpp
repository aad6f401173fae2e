// SPDX-License-Identifier: Apache-2.0
// Reflectance ("shape") functions of docs/reflectance.md and their normalizations.
//
// Shape functions equal 1 at x = 0. Functions of an angle take x in radians (the angle
// between N and H for Blinn, between V and R for Phong); functions of a cosine take
// c = cos x. Every shape is 0 for x >= pi/2 (c <= 0: light below the surface), except the
// cos^k(a x) family (cosk_shape, patent, prototype, kutlog_shape), which follows the ROM's
// rule (0 for a|x| >= pi/2) and so is nonzero slightly past pi/2 when a < 1 (n < k).
// ModelEvaluator::shape cuts every model at pi/2.
#pragma once

#include "coefficients.hpp"

#include <optional>
#include <string>
#include <vector>

namespace specular {

inline constexpr double kPi = 3.14159265358979323846;

// --- shapes ---------------------------------------------------------------------
double blinn(double x, double n);                 // cos(x)^n, the reference
double phong(double x, double n);                 // same formula; x = angle(V, R)
double cosk_shape(double x, int k, double a);     // cos(a|x|)^k for a|x| < pi/2, else 0 (ROM 12)
double patent_shape(double x, int k, double a);   // = cosk_shape
double patent(double x, int n, const CoefSpec& spec = {});  // decoder k, policy a
double prototype(double x, double n);             // cos(a x)^2, a = sqrt(n/2), zero past pi/2
double schlick(double c, double n);               // c / (n - n c + c)
double schlick_mod(double c, double n);           // c / (0.5 (n(1-c))^2 + n - n c + c)
double lyon(double c, double n, int m = 16);      // max(0, (n/m)(c-1) + 1)^m
double kutlog_shape(double x, double n, int k, double Q);  // cos^k(a x), kutlog a
double f16(double c, double n);                   // f16_norm(n) * lyon(c, n, 16) (normalized)

// --- normalizations ---------------------------------------------------------------
double blinn_phong_norm(double n);  // (n + 8) / (8 pi)
double phong_norm(double n);        // (n + 2) / (2 pi)
double f16_norm(double n);          // (n + 6) / 24.55
// 1 / (2 pi Int), Int = integral_0^gran cos(a t)^k cos t sin t dt, gran = min(pi/2, pi/(2a)):
// the factor that makes the phong-convention albedo of the kutlog shape exactly 1.
double kutlog_coef_exact(double n, int k, double Q);
// The paper's symbolic-regression fits (docs/reflectance.md#energy-normalizations); Q in [0.1, 0.4] or [0.5, 0.9],
// otherwise std::invalid_argument.
double kutlog_coef_fit(double n, int k, double Q);
// Worst absolute error of the fit, max |coef_fit * 2 pi Int - 1| over integer n in [k+1, 1000]
// (docs/reflectance.md#energy-normalizations); *n_at gets the n where it occurs.
double kutlog_fit_error(int k, double Q, int* n_at = nullptr);

// --- a model described by name, evaluable at an angle ------------------------------
enum class Model { blinn, phong, patent, prototype, schlick, schlick_mod, lyon, f16, kutlog };

std::optional<Model> parse_model(const std::string& name);  // "blinn", "schlick-mod", ...
std::string model_name(Model m);
const std::vector<std::string>& model_names();  // the CLI's model list

struct ModelParams {
  double n = 1.0;
  int k = 0;          // patent: 0 = decoder's choice; kutlog: required, 1..5
  CoefSpec coef{};    // patent only
  double Q = 0.5;     // kutlog only
  int m = 16;         // lyon only (f16 is always 16)
};

// A model bound to its parameters. shape(x) is un-normalized (1 at x = 0);
// own_norm() is the model's normalization: blinn, patent, prototype, schlick,
// schlick-mod and lyon stand in for cos^n in a Blinn-Phong pipeline and use
// (n+8)/(8 pi); phong uses (n+2)/(2 pi); f16 (n+6)/24.55; kutlog its exact coef.
struct ModelEvaluator {
  Model model = Model::blinn;
  double n = 1.0;
  int k = 0;          // exponent of the cos^k(a x) family (blinn: none, 0), lyon: m
  double a = 1.0;     // scale of the cos^k(a x) family; NaN when not of that form
  double Q = 0.5;
  int m = 16;

  double shape(double x) const;
  double operator()(double x) const { return shape(x); }
  double own_norm() const;
  bool is_cosk_family() const { return model == Model::patent || model == Model::prototype || model == Model::kutlog; }
};

// Throws std::invalid_argument on bad parameters (n < 1, kutlog without k, ...).
ModelEvaluator make_evaluator(Model model, const ModelParams& p);

}  // namespace specular
