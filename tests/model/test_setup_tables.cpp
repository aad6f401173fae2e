// SPDX-License-Identifier: Apache-2.0
// The setup's tables and shared primitives (model/host/setup_tables.hpp) against independent
// references: log2 and exp2 against long double mathematics, the arctangent table against
// atan, and the input checks (through the golden model host::fixed::setup_fixed) naming the
// field and its range.
#include "setup_tables.hpp"
#include "setup_fixed.hpp"

#include "geo_cases.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace specular;
namespace hf = specular::host::fixed;
using device::GeoSpan;
using geo_cases::kFmt;
using geo_cases::kGeo;

namespace {

long double q(int64_t code, int frac) { return std::ldexp(static_cast<long double>(code), -frac); }

}  // namespace

TEST_CASE("setup tables: log2 and exp2 against long double", "[setup_tables]") {
  long double worst_l = 0, worst_e = 0;
  std::mt19937_64 rng(11);
  for (int i = 0; i < 100000; ++i) {
    const int64_t a = std::max<int64_t>(1, static_cast<int64_t>(rng() % (uint64_t{1} << (hf::kLogUnitFrac + 1))) >> (rng() % (hf::kLogUnitFrac - 4)));
    worst_l = std::max(worst_l, std::abs(q(hf::log2_unit(a), hf::kLogFrac) - std::log2(q(a, hf::kLogUnitFrac))));
    const int64_t e = -static_cast<int64_t>(rng() % (uint64_t{1} << (hf::kLogFrac + 5)));  // 2^e for e in (-32, 0]
    const uint32_t c = hf::scale_exp2(65535, e, 65535);
    const long double want = 65535.0L * std::exp2(q(e, hf::kLogFrac));
    worst_e = std::max(worst_e, std::abs(c - want));
  }
  INFO("log2 " << static_cast<double>(worst_l) << ", C codes " << static_cast<double>(worst_e));
  CHECK(worst_l < std::ldexp(1.0L, -(hf::kLogFrac - 2)));
  CHECK(worst_e <= 0.5L + 1e-6L);  // rounded to the nearest code
  // Exact corners.
  CHECK(hf::scale_exp2(1000, 0, 65535) == 1000);
  CHECK(hf::scale_exp2(40000, int64_t{1} << hf::kLogFrac, 65535) == 65535);
  CHECK(hf::scale_exp2(0, int64_t{5} << hf::kLogFrac, 65535) == 0);
}

TEST_CASE("setup tables: the arctangent table and pi against long double", "[setup_tables]") {
  const auto& t = hf::atan_table();
  REQUIRE(t.size() == static_cast<size_t>(hf::kAtanIters));
  for (int i = 0; i < hf::kAtanIters; ++i)
    CHECK(std::abs(q(t[static_cast<size_t>(i)], hf::kAtanFrac) - std::atan(std::ldexp(1.0L, -i))) <= std::ldexp(0.5L, -hf::kAtanFrac));
  CHECK(std::abs(q(hf::atan_pi(), hf::kAtanFrac) - std::numbers::pi_v<long double>) <= std::ldexp(0.5L, -hf::kAtanFrac));
}

TEST_CASE("setup tables: the input checks reject what the interface cannot carry", "[setup_tables]") {
  GeoSpan g;
  g.n1 = g.n2 = g.h1 = g.he = {0, 0, 65536};
  CHECK_NOTHROW(hf::setup_fixed(g, kGeo, kFmt));
  GeoSpan bad = g;
  bad.n = 1024;
  CHECK_THROWS_WITH(hf::setup_fixed(bad, kGeo, kFmt), Catch::Contains("n code 1024"));
  bad = g, bad.len = 2048;
  CHECK_THROWS_WITH(hf::setup_fixed(bad, kGeo, kFmt), Catch::Contains("len 2048"));
  bad = g, bad.scale = 65536;
  CHECK_THROWS_WITH(hf::setup_fixed(bad, kGeo, kFmt), Catch::Contains("scale code"));
  bad = g, bad.h1[2] = 1 << 17;
  CHECK_THROWS_WITH(hf::setup_fixed(bad, kGeo, kFmt), Catch::Contains("vector component"));
  device::Format f = kFmt;
  f.angle_frac = 27;
  CHECK_THROWS_WITH(hf::setup_fixed(g, kGeo, f), Catch::Contains("register formats"));
}

