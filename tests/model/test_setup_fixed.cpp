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

const device::GeoFormat kGeo;
const device::Format kFmt;

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

struct Hard {
  std::string name;
  GeoSpan g;
};

GeoVec code(double x, double y, double z) { return device::quantize_vec({x, y, z}, kGeo); }

std::vector<Hard> hard_cases() {
  std::vector<Hard> h;
  auto add = [&](const std::string& name, auto edit) {
    ScanlineInput in;
    in.n1 = glm::normalize(glm::dvec3{0.1, 0.2, 1.0});
    in.n2 = glm::normalize(glm::dvec3{0.3, -0.1, 1.0});
    in.h1 = glm::normalize(glm::dvec3{0.15, 0.05, 1.0});
    in.he = in.h1;
    in.n = 50;
    in.l = 20;
    GeoSpan g = device::quantize_geo(in, kGeo, kFmt, static_cast<uint32_t>(h.size()));
    edit(g);
    h.push_back({name, g});
  };
  const int32_t vmax = static_cast<int32_t>(kGeo.vec_max()), vmin = static_cast<int32_t>(kGeo.vec_min());
  add("ordinary", [](GeoSpan&) {});
  add("N1 = N2", [](GeoSpan& s) { s.n2 = s.n1; });
  add("N1 = N2, H1 = He (flat: gamma 0)", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1; });
  add("N1 = 2 N2, H1 = 3 He (flat, non-unit)", [](GeoSpan& s) {
    s.n1 = {1000, 2000, 10000}, s.n2 = {2000, 4000, 20000}, s.h1 = {3000, 1500, 30000}, s.he = {1000, 500, 10000};
  });
  add("gamma tiny (one code)", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1, s.he[0] += 1; });
  add("gamma tiny, long span", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1, s.he[1] -= 1, s.len = 2047, s.n = 1000; });
  add("cos t1 < 0", [](GeoSpan& s) { s.h1 = s.he = code(1, 0, -0.2); });
  add("cos t1 = 0", [](GeoSpan& s) { s.n1 = s.n2 = code(0, 0, 1), s.h1 = s.he = code(1, 0, 0); });
  add("N1 = -N2", [](GeoSpan& s) { s.n2 = {-s.n1[0], -s.n1[1], -s.n1[2]}; });
  add("N1 = -3 N2", [](GeoSpan& s) { s.n1 = {3000, -6000, 9000}, s.n2 = {-1000, 2000, -3000}; });
  add("N1 = -N2 nearly (one code)", [](GeoSpan& s) { s.n2 = {-s.n1[0] + 1, -s.n1[1], -s.n1[2]}; });
  add("N1 = -N2, He along N1", [](GeoSpan& s) { s.n2 = {-s.n1[0], -s.n1[1], -s.n1[2]}, s.he = s.n1; });
  add("H2 = -H1 (N1 = N2)", [](GeoSpan& s) {
    s.n1 = s.n2 = code(0, 0, 1), s.h1 = code(0.6, 0, 0.8), s.he = {-s.h1[0], -s.h1[1], -s.h1[2]};
  });
  add("H2 = -H1 (a quarter turn)", [](GeoSpan& s) {
    s.n1 = {0, 0, 40000}, s.n2 = {40000, 0, 0}, s.h1 = {0, 30000, 40000}, s.he = {-40000, -30000, 0};
  });
  add("L = -V: H1 zero", [](GeoSpan& s) { s.h1 = {0, 0, 0}; });
  add("L = -V: He zero", [](GeoSpan& s) { s.he = {0, 0, 0}; });
  add("non-unit vectors", [](GeoSpan& s) {
    s.n1 = code(0.03, 0.06, 0.3), s.n2 = code(0.45, -0.15, 1.5), s.h1 = code(0.27, 0.09, 1.8), s.he = code(0.0015, 0.0005, 0.01);
  });
  add("tiny vectors (a few codes)", [](GeoSpan& s) { s.n1 = {0, 0, 1}, s.n2 = {1, 0, 2}, s.h1 = {1, 1, 3}, s.he = {0, 1, 1}; });
  add("tiny vectors, flat", [](GeoSpan& s) { s.n1 = s.n2 = {1, -1, 1}, s.h1 = s.he = {0, 0, 1}; });
  add("maximum vectors", [vmax, vmin](GeoSpan& s) {
    s.n1 = {vmax, vmax, vmax}, s.n2 = {vmin, vmax, vmax}, s.h1 = {vmax, vmin / 2, vmax}, s.he = {vmin, vmin, vmax};
  });
  add("maximum and tiny", [vmax](GeoSpan& s) { s.n1 = {vmax, 0, vmax}, s.n2 = {1, 0, 1}, s.h1 = {0, 1, 1}, s.he = {vmax, vmax, vmax}; });
  add("zero N1", [](GeoSpan& s) { s.n1 = {0, 0, 0}; });
  add("zero N2", [](GeoSpan& s) { s.n2 = {0, 0, 0}; });
  add("zero N1 and H1", [](GeoSpan& s) { s.n1 = {0, 0, 0}, s.h1 = {0, 0, 0}; });
  add("n = 0", [](GeoSpan& s) { s.n = 0; });
  add("n = 1001", [](GeoSpan& s) { s.n = kMaxN + 1; });
  add("n = 1023", [](GeoSpan& s) { s.n = 1023; });
  add("l = 0", [](GeoSpan& s) { s.len = 0; });
  add("l = 2047", [](GeoSpan& s) { s.len = kMaxLen; });
  add("l = 2047, n = 1000", [](GeoSpan& s) { s.len = kMaxLen, s.n = 1000; });
  for (uint32_t n : {1u, 2u, 3u, 4u, 5u, 7u, 10u, 14u, 999u, 1000u})
    add("n = " + std::to_string(n), [n](GeoSpan& s) { s.n = n; });
  add("psi crosses 0", [](GeoSpan& s) {
    s.n1 = code(0, 0, 1), s.n2 = code(0.2, 0, 1), s.h1 = s.he = code(0.1, 0, 1), s.n = 1000, s.len = 400;
  });
  add("psi beyond pi/2", [](GeoSpan& s) {
    s.n1 = code(0, 0, 1), s.n2 = code(1, 0, 0), s.h1 = s.he = code(-1, 0, 0.3), s.len = 300, s.n = 1;
  });
  add("scale 0", [](GeoSpan& s) { s.scale = 0; });
  add("scale at the maximum, A = 1", [](GeoSpan& s) { s.n2 = s.n1, s.h1 = s.he = s.n1, s.scale = 65535; });
  add("C saturates? scale maximum", [](GeoSpan& s) { s.scale = 65535, s.n = 1; });
  return h;
}

// Spans of the interface: host::random_spans quantized, with vectors of every length the
// interface carries (unit, shortened like a rasterizer's lerped normals, tiny, up to the
// maximum) and a share of flat spans.
std::vector<GeoSpan> random_geo_spans(size_t count, uint64_t seed) {
  const std::vector<ScanlineInput> in = host::random_spans(count, seed);
  std::mt19937_64 rng(seed ^ 0x5e7f13edULL);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<GeoSpan> out;
  out.reserve(count);
  for (size_t i = 0; i < in.size(); ++i) {
    ScanlineInput s = in[i];
    if (u01(rng) < 0.3) s.n2 = s.n1, s.he = s.h1;
    for (glm::dvec3* v : {&s.n1, &s.n2, &s.h1, &s.he}) {
      const double k = u01(rng);
      const double f = k < 0.4 ? 1.0 : k < 0.7 ? 0.5 + 0.5 * u01(rng) : k < 0.85 ? std::exp2(-16.0 + 12.0 * u01(rng))
                                                                                  : 1.0 + 0.73 * u01(rng);
      *v *= f;
    }
    out.push_back(device::quantize_geo(s, kGeo, kFmt, static_cast<uint32_t>(i)));
  }
  return out;
}

}  // namespace

TEST_CASE("fixed setup: rsqrt and normalize against long double", "[setup_fixed]") {
  long double worst_r = 0, worst_u = 0;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200000; ++i) {
    const uint64_t m = (uint64_t{1} << 46) + rng() % (3 * (uint64_t{1} << 46));
    const long double want = 1.0L / std::sqrt(std::ldexp(static_cast<long double>(m), -48));
    worst_r = std::max(worst_r, std::abs(q(hf::rsqrt_norm(m), hf::kRsqrtFrac) / want - 1.0L));
  }
  for (uint64_t m : {uint64_t{1} << 46, (uint64_t{1} << 48) - 1}) {
    const long double want = 1.0L / std::sqrt(std::ldexp(static_cast<long double>(m), -48));
    worst_r = std::max(worst_r, std::abs(q(hf::rsqrt_norm(m), hf::kRsqrtFrac) / want - 1.0L));
  }
  for (int i = 0; i < 100000; ++i) {
    // Integer codes of every size, and Q44 vectors of every length from 2^-40 to 2.
    hf::Vec v{};
    const int bits = 1 + static_cast<int>(rng() % (i % 2 ? 18 : 47));
    for (auto& c : v) c = static_cast<int64_t>(rng() % (uint64_t{1} << bits)) - (int64_t{1} << (bits - 1));
    const hf::Vec u = hf::normalize(v);
    long double len = 0;
    for (auto c : v) len += static_cast<long double>(c) * c;
    len = std::sqrt(len);
    for (size_t k = 0; k < 3; ++k)
      if (len > 0) worst_u = std::max(worst_u, std::abs(q(u[k], hf::kUnitFrac) - v[k] / len));
  }
  INFO("rsqrt relative " << static_cast<double>(worst_r) << ", unit vector component " << static_cast<double>(worst_u));
  CHECK(worst_r < 0x1p-46L);
  CHECK(worst_u < 0x1p-44L);
  CHECK(hf::normalize({0, 0, 0}) == hf::Vec{0, 0, 0});
  CHECK_THROWS(hf::rsqrt_norm(uint64_t{1} << 45));
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
    worst_m = std::max(worst_m, std::abs(q(p.mag_k, hf::kCordicFrac) * q(hf::cordic_inv_gain(), hf::kCordicFrac) -
                                         std::hypot(xa, ya)));
  }
  for (int i = 0; i < 100000; ++i) {
    const int64_t a = std::max<int64_t>(1, static_cast<int64_t>(rng() % (uint64_t{1} << 45)) >> (rng() % 40));
    worst_l = std::max(worst_l, std::abs(q(hf::log2_q44(a), hf::kLogFrac) - std::log2(q(a, hf::kUnitFrac))));
    const int64_t e = -static_cast<int64_t>(rng() % (uint64_t{1} << 45));  // 2^e for e in (-32, 0]
    const uint32_t c = hf::scale_exp2(65535, e, 65535);
    const long double want = 65535.0L * std::exp2(q(e, hf::kLogFrac));
    worst_e = std::max(worst_e, std::abs(c - want));
  }
  INFO("atan2 " << static_cast<double>(worst_a) << " rad |v|, |v| " << static_cast<double>(worst_m) << ", log2 "
                << static_cast<double>(worst_l) << ", C codes " << static_cast<double>(worst_e));
  CHECK(worst_a < 0x1p-44L);
  CHECK(worst_m < 0x1p-43L);
  CHECK(worst_l < 0x1p-36L);
  CHECK(worst_e <= 0.5L + 1e-6L);  // rounded to the nearest code
  // Exact corners.
  CHECK(hf::cordic_vectoring(-(int64_t{1} << 48), 0).angle == Approx(static_cast<double>(hf::pi_q48())).margin(4));
  CHECK(hf::scale_exp2(1000, 0, 65535) == 1000);
  CHECK(hf::scale_exp2(40000, int64_t{1} << hf::kLogFrac, 65535) == 65535);
  CHECK(hf::scale_exp2(0, int64_t{5} << hf::kLogFrac, 65535) == 0);
}

TEST_CASE("fixed setup: every hard case gets the scalar setup's status and pixels", "[setup_fixed]") {
  std::vector<int> seen(5, 0);
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
  }
  for (int s = 0; s < 5; ++s) CHECK(seen[static_cast<size_t>(s)] > 0);
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
