// SPDX-License-Identifier: Apache-2.0
// The two-bank blend's fit (model/reference/blend.hpp, docs/display_exact.md#coefficients) against
// independent evaluations: closed forms, the x^4 series, and a dense long double sweep with a
// brute-force search around the fit.
#include "blend.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace specular;

namespace {

// max over x in [0, pi/2] of |B(x) - cos^n(x)| in long double, `points` uniform samples of
// [0, min(pi/2, sqrt(60/n))] (past it every term is below e^-30): written apart from blend.cpp.
long double sweep(int n, int k1, long double a1, int k2, long double a2, long double t, int points) {
  const long double half_pi = std::numbers::pi_v<long double> / 2;
  const long double end = std::min(half_pi, std::sqrt(60.0L / n));
  auto term = [&](int k, long double a, long double x) {
    return a * x < half_pi ? std::pow(std::cos(a * x), static_cast<long double>(k)) : 0.0L;
  };
  long double worst = 0.0L;
  for (int i = 0; i <= points; ++i) {
    const long double x = end * i / points;
    const long double b = (1 - t) * term(k1, a1, x) + t * term(k2, a2, x);
    worst = std::max(worst, std::abs(b - std::pow(std::cos(x), static_cast<long double>(n))));
  }
  return worst;
}

}  // namespace

TEST_CASE("blend: n equal to a bank is that bank alone, exact", "[blend]") {
  const int n = GENERATE(1, 2, 4, 16, 64, 256);
  const BlendCoef c = blend_minimax(n, n, n == 256 ? 1024 : 4 * n);
  CHECK(c.t == 0.0);
  CHECK(c.a1 == 1.0);
  CHECK(c.max_abs == 0.0);
}

TEST_CASE("blend: the maclaurin weight cancels the x^4 term of the two banks", "[blend]") {
  // ln cos x = -x^2/2 - x^4/12 - ..., so cos^k(sqrt(n/k) x) = cos^n(x) (1 - (n^2/k - n) x^4/12 + O(x^6)):
  // one bank errs by (n^2/k1 - n)/12 x^4, the blend with t = (1/k1 - 1/n)/(1/k1 - 1/k2) by O(x^6).
  const int n = GENERATE(3, 5, 10, 40, 700);
  int k1 = 0, k2 = 0;
  blend_banks({1, 2, 4, 16, 64, 256, 1024}, n, k1, k2);
  const BlendCoef c = blend_maclaurin(n, k1, k2);
  const double x = 0.05 / std::sqrt(static_cast<double>(n));
  const double single = (static_cast<double>(n) * n / k1 - n) / 12.0 * std::pow(x, 4);
  const double err = std::abs(blend_value(c, x) - std::pow(std::cos(x), n));
  CHECK(err < 0.02 * single);
  CHECK(std::abs(c.t - (1.0 / k1 - 1.0 / n) / (1.0 / k1 - 1.0 / k2)) < 1e-15);
}

TEST_CASE("blend: the minimax fit against a dense long double sweep and a brute-force search", "[blend]") {
  const auto [n, banks] = GENERATE(table<int, std::vector<int>>({{3, {1, 2, 4, 16, 64, 256, 1024}},
                                                                 {5, {1, 2, 3, 4, 8, 16, 64, 256, 1024}},
                                                                 {6, {1, 2, 4, 16, 64, 256, 1024}},
                                                                 {40, {1, 2, 4, 16, 64, 256, 1024}},
                                                                 {700, {1, 2, 4, 16, 64, 256, 1024}}}));
  int k1 = 0, k2 = 0;
  blend_banks(banks, n, k1, k2);
  const BlendCoef c = blend_minimax(n, k1, k2);
  REQUIRE(c.k1 == k1);
  REQUIRE(c.k2 == k2);
  CHECK(c.t >= 0.0);
  CHECK(c.t <= 1.0);
  // The fit's own figure is the error of its coefficients (to 1 %: it samples 2400 points).
  const long double e = sweep(n, k1, c.a1, k2, c.a2, c.t, 40000);
  CHECK(std::abs(static_cast<double>(e) - c.max_abs) <= 0.01 * static_cast<double>(e));
  // Better than its starting point, the x^4 cancellation.
  const BlendCoef m = blend_maclaurin(n, k1, k2);
  CHECK(e <= sweep(n, k1, m.a1, k2, m.a2, m.t, 20000));
  // No point of a 5 x 5 x 5 grid around it (a1, a2 within 0.4 %, t within 0.02) does better by 1 %.
  long double best = e;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int l = -2; l <= 2; ++l)
        best = std::min(best,
                        sweep(n, k1, c.a1 * (1 + 0.002L * i), k2, c.a2 * (1 + 0.002L * j), c.t + 0.01L * l, 2000));
  CHECK(best >= 0.99L * e);
}

TEST_CASE("blend: the worst n of two bank sets, measured (docs/display_exact.md#measured)", "[blend]") {
  // The worst n of each set: {1,2,4,16,...} at n = 3 (banks 2 and 4) and {1,2,3,4,8,16,...} at
  // n = 5 (banks 4 and 8), against the long double sweep.
  const BlendCoef a = blend_minimax(3, 2, 4);
  CHECK(static_cast<double>(sweep(3, 2, a.a1, 4, a.a2, a.t, 20000)) == Approx(1.08e-3).epsilon(0.01));
  const BlendCoef b = blend_minimax(5, 4, 8);
  CHECK(static_cast<double>(sweep(5, 4, b.a1, 8, b.a2, b.t, 20000)) == Approx(2.13e-4).epsilon(0.01));
}

TEST_CASE("blend: bad input is refused naming it", "[blend]") {
  int k1 = 0, k2 = 0;
  REQUIRE_THROWS_WITH(blend_banks({2, 4}, 1, k1, k2), Catch::Contains("n = 1"));
  REQUIRE_THROWS_WITH(blend_banks({1, 4, 4}, 5, k1, k2), Catch::Contains("strictly increasing"));
  REQUIRE_THROWS_WITH(blend_minimax(5, 8, 16), Catch::Contains("k1 <= n < k2"));
  REQUIRE_THROWS_WITH(blend_minimax(1001, 16, 64), Catch::Contains("1..1000"));
  blend_banks({1, 2, 4}, 9, k1, k2);  // past the last bank: the last bank twice
  CHECK(k1 == 4);
  CHECK(k2 == 4);
}
