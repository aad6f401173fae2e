// SPDX-License-Identifier: Apache-2.0
// The fixed-point setup (model/host/setup_fixed.hpp, docs/setup_hw.md) against
// independent references: its primitives against long double mathematics, and the whole
// setup against the scalar double setup on the exact input values,
// scanline_setup(geo_input(span)): the same status on every hard case of
// docs/scanline_setup.md#hard-cases, and on random spans the pixels C cos^n(psi_i) within
// 0.01 % relative in the epicenter + 1 LSB of C (host::compare_pixels).
// SPECULAR_SETUP_FIXED_SPANS=N runs N random spans instead of 20,000 (the long option).
#include "setup_fixed.hpp"

#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"
#include "setup_batch.hpp"
#include "geo_cases.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace specular;
namespace hf = specular::host::fixed;
using device::GeoSpan;
using device::GeoVec;

namespace {

using geo_cases::Hard;
using geo_cases::hard_cases;
using geo_cases::kFmt;
using geo_cases::kGeo;
using geo_cases::random_geo_spans;

long double q(int64_t code, int frac) { return std::ldexp(static_cast<long double>(code), -frac); }

// The reference registers and status of a span: the scalar double setup on its exact values.
struct Ref {
  device::Registers reg;
  SetupStatus status;
};
Ref reference(const GeoSpan& g) {
  const ScanlineInput in = device::geo_input(g, kGeo, kFmt);
  return {host::span_registers(in, kFmt), scanline_setup(in).status};
}

}  // namespace

TEST_CASE("fixed setup: rsqrt and normalize against long double", "[setup_fixed]") {
  long double worst_r = 0, worst_u = 0;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200000; ++i) {
    const uint64_t m = (uint64_t{1} << (hf::kRsqrtInBits - 2)) + rng() % (3 * (uint64_t{1} << (hf::kRsqrtInBits - 2)));
    const long double want = 1.0L / std::sqrt(std::ldexp(static_cast<long double>(m), -hf::kRsqrtInBits));
    worst_r = std::max(worst_r, std::abs(q(hf::rsqrt_norm(m), hf::kRsqrtFrac) / want - 1.0L));
  }
  for (uint64_t m : {uint64_t{1} << (hf::kRsqrtInBits - 2), (uint64_t{1} << hf::kRsqrtInBits) - 1}) {
    const long double want = 1.0L / std::sqrt(std::ldexp(static_cast<long double>(m), -hf::kRsqrtInBits));
    worst_r = std::max(worst_r, std::abs(q(hf::rsqrt_norm(m), hf::kRsqrtFrac) / want - 1.0L));
  }
  for (int i = 0; i < 100000; ++i) {
    // Integer codes of every size, and Q30 vectors of every length from 2^-29 to 1.7.
    hf::Vec v{};
    const int bits = 1 + static_cast<int>(rng() % (i % 2 ? 24 : hf::kUnitFrac + 1));
    for (auto& c : v) c = static_cast<int64_t>(rng() % (uint64_t{1} << bits)) - (int64_t{1} << (bits - 1));
    const hf::Vec u = hf::normalize(v);
    long double len = 0;
    for (auto c : v) len += static_cast<long double>(c) * c;
    len = std::sqrt(len);
    for (size_t k = 0; k < 3; ++k)
      if (len > 0) worst_u = std::max(worst_u, std::abs(q(u[k], hf::kUnitFrac) - v[k] / len));
  }
  INFO("rsqrt relative " << static_cast<double>(worst_r) << ", unit vector component " << static_cast<double>(worst_u));
  CHECK(worst_r < std::ldexp(1.0L, -(hf::kRsqrtFrac - 1)));
  CHECK(worst_u < std::ldexp(1.0L, -(hf::kUnitFrac - 1)));
  CHECK(hf::normalize({0, 0, 0}) == hf::Vec{0, 0, 0});
  CHECK_THROWS(hf::rsqrt_norm(uint64_t{1} << (hf::kRsqrtInBits - 3)));
}

TEST_CASE("fixed setup: CORDIC, log2 and exp2 against long double", "[setup_fixed]") {
  long double worst_a = 0, worst_m = 0, worst_l = 0, worst_e = 0;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<long double> ang(-std::numbers::pi_v<long double>, std::numbers::pi_v<long double>);
  for (int i = 0; i < 100000; ++i) {
    const long double t = ang(rng), r = std::ldexp(1.0L, -static_cast<int>(rng() % 30)) * (1.0L + (rng() % 1000) / 1000.0L);
    const auto x = static_cast<int64_t>(std::llround(std::ldexp(r * std::cos(t), hf::kCordicFrac)));
    const auto y = static_cast<int64_t>(std::llround(std::ldexp(r * std::sin(t), hf::kCordicFrac)));
    const hf::Polar p = hf::cordic_vectoring(x, y);
    const long double xa = q(x, hf::kCordicFrac), ya = q(y, hf::kCordicFrac);
    // The angle's error is absolute in the plane: relative to the vector's length r.
    worst_a = std::max(worst_a, r * std::abs(q(p.angle, hf::kCordicFrac) - std::atan2(ya, xa)));
    worst_m = std::max(worst_m, std::abs(q(p.mag_k, hf::kCordicFrac) * q(hf::cordic_inv_gain(), hf::kGainFrac) -
                                         std::hypot(xa, ya)));
  }
  for (int i = 0; i < 100000; ++i) {
    const int64_t a = std::max<int64_t>(1, static_cast<int64_t>(rng() % (uint64_t{1} << (hf::kUnitFrac + 1))) >> (rng() % (hf::kUnitFrac - 4)));
    worst_l = std::max(worst_l, std::abs(q(hf::log2_unit(a), hf::kLogFrac) - std::log2(q(a, hf::kUnitFrac))));
    const int64_t e = -static_cast<int64_t>(rng() % (uint64_t{1} << (hf::kLogFrac + 5)));  // 2^e for e in (-32, 0]
    const uint32_t c = hf::scale_exp2(65535, e, 65535);
    const long double want = 65535.0L * std::exp2(q(e, hf::kLogFrac));
    worst_e = std::max(worst_e, std::abs(c - want));
  }
  INFO("atan2 " << static_cast<double>(worst_a) << " rad |v|, |v| " << static_cast<double>(worst_m) << ", log2 "
                << static_cast<double>(worst_l) << ", C codes " << static_cast<double>(worst_e));
  CHECK(worst_a < std::ldexp(1.0L, -(hf::kCordicFrac - 5)));
  CHECK(worst_m < std::ldexp(1.0L, -(hf::kGainFrac + 1)));  // 1/K in Q30
  CHECK(worst_l < std::ldexp(1.0L, -(hf::kLogFrac - 2)));
  CHECK(worst_e <= 0.5L + 1e-6L);  // rounded to the nearest code
  // Exact corners.
  CHECK(hf::cordic_vectoring(-(int64_t{1} << hf::kCordicFrac), 0).angle == Approx(static_cast<double>(hf::cordic_pi())).margin(4));
  CHECK(hf::scale_exp2(1000, 0, 65535) == 1000);
  CHECK(hf::scale_exp2(40000, int64_t{1} << hf::kLogFrac, 65535) == 65535);
  CHECK(hf::scale_exp2(0, int64_t{5} << hf::kLogFrac, 65535) == 0);
}

TEST_CASE("fixed setup: every hard case gets the scalar setup's status and pixels", "[setup_fixed]") {
  std::vector<int> seen(5, 0);
  double worst = 0;
  for (const Hard& h : hard_cases()) {
    INFO(h.name);
    const hf::Result got = hf::setup_fixed(h.g, kGeo, kFmt);
    const Ref ref = reference(h.g);
    seen.at(static_cast<size_t>(ref.status))++;
    CHECK(got.status == ref.status);
    CHECK(got.span.tag == h.g.tag);
    CHECK(got.span.reg.n == ref.reg.n);
    CHECK(got.span.reg.len == ref.reg.len);
    if (ref.status == SetupStatus::invalid_input || ref.status == SetupStatus::undefined_halfway) {
      CHECK(got.span.reg.c == 0);
      CHECK(got.span.reg.psi0 == 0);
      CHECK(got.span.reg.dpsi == 0);
    }
    const auto a = host::compare_pixels(got.span.reg, ref.reg, kFmt);
    INFO("C " << got.span.reg.c << " / " << ref.reg.c << ", psi0 " << got.span.reg.psi0 << " / " << ref.reg.psi0
              << ", dpsi " << got.span.reg.dpsi << " / " << ref.reg.dpsi << "; worst " << a.worst << " at pixel "
              << a.worst_pixel << ", " << a.max_abs_lsb << " LSB");
    CHECK(a.ok());
    worst = std::max(worst, a.worst);
  }
  for (int s = 0; s < 5; ++s) CHECK(seen[static_cast<size_t>(s)] > 0);
  WARN("fixed setup, " << hard_cases().size() << " hard cases: worst " << worst << " of the allowance");
}

TEST_CASE("fixed setup: near-opposite halfway codes get the scalar setup's status and pixels", "[setup_fixed]") {
  // He one to a few codes away from -H1 (N1 = N2): |H1 + H2| from about 1e-11 up, above the
  // scalar setup's opposite-halfway threshold of 1e-12, so an ordinary span there; the
  // fixed-point floor must sit below it (docs/setup_hw.md#error-budget).
  const int d = GENERATE(0, 1, 2, 3, 5, 30);
  const int y = GENERATE(1, 7);
  GeoSpan g;
  g.n1 = g.n2 = {0, 0, 65536};
  g.h1 = {131071, y, 0};
  g.he = {-131071 + d, -y, 0};
  g.n = 100, g.len = 100, g.scale = 30000;
  INFO("d " << d << ", y " << y);
  const hf::Result got = hf::setup_fixed(g, kGeo, kFmt);
  const Ref ref = reference(g);
  CHECK(got.status == ref.status);
  CHECK(ref.status == (d == 0 ? SetupStatus::opposite_halfway : SetupStatus::ok));
  CHECK(host::compare_pixels(got.span.reg, ref.reg, kFmt).ok());
}

TEST_CASE("fixed setup agrees with the scalar setup on random spans", "[setup_fixed]") {
  const char* env = std::getenv("SPECULAR_SETUP_FIXED_SPANS");
  const size_t total = env ? std::strtoull(env, nullptr, 10) : 20000;
  const size_t chunk = 1 << 16;
  size_t spans = 0, status_diff = 0, fails = 0, codes_equal = 0;
  double worst = 0, rel = 0, lsb = 0;
  for (size_t done = 0; done < total; done += chunk) {
    for (const GeoSpan& g : random_geo_spans(std::min(chunk, total - done), 20261203 + done)) {
      ++spans;
      const hf::Result got = hf::setup_fixed(g, kGeo, kFmt);
      const Ref ref = reference(g);
      if (got.status != ref.status || got.span.reg.n != ref.reg.n || got.span.reg.len != ref.reg.len) {
        ++status_diff;
        continue;
      }
      codes_equal += got.span.reg.c == ref.reg.c && got.span.reg.psi0 == ref.reg.psi0 && got.span.reg.dpsi == ref.reg.dpsi;
      const auto a = host::compare_pixels(got.span.reg, ref.reg, kFmt);
      fails += !a.ok();
      worst = std::max(worst, a.worst), rel = std::max(rel, a.max_rel_epicenter), lsb = std::max(lsb, a.max_abs_lsb);
    }
  }
  INFO(spans << " spans, worst " << worst << " of the allowance");
  CHECK(spans == total);
  CHECK(status_diff == 0);
  CHECK(fails == 0);
  WARN("fixed setup, " << spans << " random spans: worst " << worst << " of the allowance, max rel " << rel
                       << " in the epicenter (Pref >= 2^-10), max " << lsb << " LSB; all three codes equal on "
                       << codes_equal << " spans");
}

TEST_CASE("fixed setup rejects input the interface cannot carry", "[setup_fixed]") {
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

