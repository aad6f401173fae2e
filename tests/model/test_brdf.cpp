// SPDX-License-Identifier: Apache-2.0
// Shape functions against values worked out by hand from their closed forms.
#include "brdf.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace specular;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("every shape is 1 at x = 0 and 0 past pi/2", "[brdf]") {
  const double n = GENERATE(1.0, 2.0, 7.0, 100.0, 1000.0);
  for (const auto& name : model_names()) {
    ModelParams p;
    p.n = n;
    p.k = name == "kutlog" ? 3 : 0;
    p.Q = 0.4;
    const ModelEvaluator ev = make_evaluator(*parse_model(name), p);
    INFO(name << " n=" << n);
    CHECK_THAT(ev(0.0), WithinAbs(1.0, 1e-15));
    CHECK(ev(1.6) == 0.0);
    CHECK(ev(3.0) == 0.0);
  }
}

TEST_CASE("closed-form values of the shapes", "[brdf]") {
  // cos(pi/3) = 1/2.
  const double x = std::acos(0.5);
  CHECK_THAT(blinn(x, 3), WithinRel(0.125, 1e-14));
  // schlick: c / (n - n c + c) at c = 1/2, n = 4: 0.5 / (4 - 2 + 0.5) = 0.2.
  CHECK_THAT(schlick(0.5, 4), WithinRel(0.2, 1e-14));
  // schlick-mod: u = n(1-c) = 2: 0.5 / (0.5*4 + 2.5) = 1/9.
  CHECK_THAT(schlick_mod(0.5, 4), WithinRel(1.0 / 9.0, 1e-14));
  // lyon m = 16, n = 8, c = 1/2: (8/16 * -1/2 + 1)^16 = 0.75^16.
  CHECK_THAT(lyon(0.5, 8, 16), WithinRel(std::pow(0.75, 16), 1e-14));
  // lyon is clamped to 0 where the base is negative: n = 64, c = 0.5 -> 1 - 2 < 0.
  CHECK(lyon(0.5, 64, 16) == 0.0);
  // f16 = (n+6)/24.55 * lyon-16.
  CHECK_THAT(f16(0.5, 8), WithinRel(14.0 / 24.55 * std::pow(0.75, 16), 1e-14));
  // prototype n = 8: a = 2, cos^2(2 x) at x = pi/8 -> cos^2(pi/4) = 1/2.
  CHECK_THAT(prototype(kPi / 8, 8), WithinRel(0.5, 1e-14));
  // prototype is cut at a x = pi/2: x = pi/4 + tiny is 0.
  CHECK(prototype(kPi / 4 + 1e-12, 8) == 0.0);
  // cos is even, the ROM uses |zeta|.
  CHECK(cosk_shape(-0.3, 4, 2.0) == cosk_shape(0.3, 4, 2.0));
}

TEST_CASE("schlick-mod matches exp(-u) to second order in u = n(1-c)", "[brdf]") {
  // 1 / (1 + u + u^2/2) = 1 - u + u^2/2 + O(u^3) for c -> 1 at fixed u: check the
  // difference shrinks like u^3 (independent of the code: the series of exp).
  const double n = 1000.0;
  for (double u : {1e-2, 5e-3}) {
    const double c = 1.0 - u / n;
    const double d = std::abs(schlick_mod(c, n) - std::exp(-u));
    CHECK(d < 2.0 * u * u * u);
  }
}

TEST_CASE("kutlog matches blinn exactly at level Q", "[brdf]") {
  // Definition of the 2023 paper's a: cos^k(a x_Q) = Q where cos^n(x_Q) = Q.
  const double Q = GENERATE(0.1, 0.3, 0.5, 0.9);
  const int k = GENERATE(1, 2, 5);
  const double n = 50.0;
  const double xq = std::acos(std::pow(Q, 1.0 / n));
  CHECK_THAT(kutlog_shape(xq, n, k, Q), WithinRel(Q, 1e-12));
}

TEST_CASE("normalizations", "[brdf]") {
  CHECK_THAT(blinn_phong_norm(8), WithinRel(16.0 / (8.0 * kPi), 1e-15));
  CHECK_THAT(phong_norm(2), WithinRel(2.0 / kPi, 1e-15));
  CHECK_THAT(f16_norm(18.55), WithinRel(1.0, 1e-15));
  // Fits of docs/reflectance.md#energy-normalizations, evaluated by hand: Q = 0.5, k = 2, n = 100:
  // 0.743*0.5*(-0.0133*2*100 + 16.7)/2 + 16.7 + 0.245 = 18.30549...
  CHECK_THAT(kutlog_coef_fit(100, 2, 0.5), WithinRel(0.3715 * (16.7 - 2.66) / 2 + 16.945, 1e-12));
  // Q = 0.3, k = 1, n = 10: 0.608*10*0.107/2.6 + 1.61 + 0.284.
  CHECK_THAT(kutlog_coef_fit(10, 1, 0.3), WithinRel(6.08 * 0.107 / 2.6 + 1.894, 1e-12));
  CHECK_THROWS_AS(kutlog_coef_fit(10, 1, 0.45), std::invalid_argument);
}

TEST_CASE("kutlog exact coef against a closed-form integral (k = 2)", "[brdf]") {
  // Int = integral_0^g cos^2(a t) cos t sin t dt, g = min(pi/2, pi/(2a)):
  // cos^2(a t) = (1 + cos 2at)/2, cos t sin t = sin(2t)/2, so
  // Int = 1/4 [ -cos(2t)/2 + ( -cos((2a+2)t)/(2a+2) + cos((2a-2)t)/(2a-2) )/2 ]_0^g  (a != 1).
  const double n = GENERATE(10.0, 100.0, 1000.0);
  const double Q = 0.5;
  const double a = std::acos(std::pow(Q, 0.5)) / std::acos(std::pow(Q, 1.0 / n));
  const double g = std::min(kPi / 2, kPi / (2 * a));
  auto F = [&](double t) {
    return 0.25 * (-std::cos(2 * t) / 2 +
                   0.5 * (-std::cos((2 * a + 2) * t) / (2 * a + 2) + std::cos((2 * a - 2) * t) / (2 * a - 2)));
  };
  const double integral = F(g) - F(0.0);
  CHECK_THAT(kutlog_coef_exact(n, 2, Q), WithinRel(1.0 / (2 * kPi * integral), 1e-9));
}

TEST_CASE("kutlog fit error against the closed-form integral (k = 2)", "[brdf]") {
  const double Q = GENERATE(0.3, 0.7);
  auto closed = [&](double n) {  // |fit * 2 pi Int - 1| with Int in closed form (see above)
    const double a = std::acos(std::pow(Q, 0.5)) / std::acos(std::pow(Q, 1.0 / n));
    const double g = std::min(kPi / 2, kPi / (2 * a));
    auto F = [&](double t) {
      return 0.25 * (-std::cos(2 * t) / 2 +
                     0.5 * (-std::cos((2 * a + 2) * t) / (2 * a + 2) + std::cos((2 * a - 2) * t) / (2 * a - 2)));
    };
    return std::abs(kutlog_coef_fit(n, 2, Q) * 2 * kPi * (F(g) - F(0.0)) - 1);
  };
  int at = 0;
  const double worst = kutlog_fit_error(2, Q, &at);
  REQUIRE(at >= 3);
  REQUIRE(at <= kMaxN);
  CHECK_THAT(worst, WithinRel(closed(at), 1e-6));
  for (double n : {3.0, 10.0, 100.0, 1000.0}) CHECK(closed(n) <= worst * (1 + 1e-6));
}

TEST_CASE("make_evaluator rejects bad parameters", "[brdf]") {
  ModelParams p;
  p.n = 0.5;
  CHECK_THROWS_AS(make_evaluator(Model::blinn, p), std::invalid_argument);
  p.n = 10;
  CHECK_THROWS_AS(make_evaluator(Model::kutlog, p), std::invalid_argument);  // k missing
  CHECK_FALSE(parse_model("phongg").has_value());
  CHECK(model_name(*parse_model("schlick-mod")) == "schlick-mod");
}
