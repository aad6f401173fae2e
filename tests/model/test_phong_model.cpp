// SPDX-License-Identifier: Apache-2.0
// The golden model of phong_stream (model/device/phong_model.hpp, docs/phong_hw.md): bit-level
// properties of its arithmetic and ROMs, one named test per hard case, and its agreement with
// per-pixel Blinn-Phong in double (phong_exact, phong_truth) at the device's budget.
// Expected values come from closed forms, symmetries of the exact interpolation, or the
// double references, never from the model's own output.
#include "metrics.hpp"
#include "phong_error.hpp"
#include "phong_model.hpp"
#include "phong_spans.hpp"
#include "scanline_setup.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>
#include <string>

using namespace specular;
using namespace specular::device;
using specular::test::random_unit;
using specular::test::span_of;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double kHalfPi = 1.57079632679489661923;

// A random span whose normals lie within `spread` radians of H (so the lobe is crossed).
GeoSpan random_span(const PhongFormat& f, std::mt19937_64& rng, int n_max) {
  std::uniform_int_distribution<int> nd(1, n_max), ld(0, f.max_len());
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  const glm::dvec3 h1 = random_unit(rng);
  const glm::dvec3 he = f.const_h ? h1 : glm::normalize(h1 + 0.3 * random_unit(rng));
  const double spread = ud(rng) < 0.5 ? 0.1 : 1.0;
  const glm::dvec3 n1 = glm::normalize(h1 + spread * random_unit(rng));
  const glm::dvec3 n2 = glm::normalize(h1 + spread * random_unit(rng));
  const int l = ud(rng) < 0.3 ? f.max_len() : ld(rng);
  return span_of(f, n1, n2, h1, he, nd(rng), l, 0.25 + 1.7 * ud(rng), static_cast<uint32_t>(rng()));
}

// The budget of the device (docs/metrics.md): |err| <= 0.10 % ref + 1 LSB in the epicenter
// (n = 1: where ref >= 4 LSB), |err| <= 0.01 C + 1 LSB everywhere.
void check_budget(const PhongModel& m, const GeoSpan& s) {
  const PhongFormat& f = m.format();
  const double lsb = std::ldexp(1.0, -f.c_frac);
  const double c = std::ldexp(static_cast<double>(s.scale), -f.c_frac);
  const double xe = epicenter_end(static_cast<double>(s.n));
  for (int i = 0; i <= static_cast<int>(s.len); ++i) {
    double cosv = 0.0;
    const double ref = phong_exact(s, f, i, &cosv);
    const double got = std::ldexp(static_cast<double>(m.pixel(s, i)), -f.c_frac);
    const double err = std::abs(got - ref);
    INFO("n=" << s.n << " l=" << s.len << " i=" << i << " psi=" << std::acos(cosv) << " ref=" << ref << " got=" << got);
    REQUIRE(err <= 0.01 * c + lsb);
    if (cosv > 0.0 && std::acos(cosv) <= xe && ref >= 4 * lsb) REQUIRE(err <= 1e-3 * ref + lsb);
  }
}

GeoSpan reversed(GeoSpan s) {
  std::swap(s.n1, s.n2);
  std::swap(s.h1, s.he);
  return s;
}

}  // namespace

TEST_CASE("phong: the format validates every field and names it", "[phong]") {
  PhongFormat f;
  REQUIRE_NOTHROW(f.validate());
  f.op_bits = 40;
  REQUIRE_THROWS_WITH(f.validate(), Catch::Contains("op_bits"));
  f = PhongFormat{};
  f.newton = 3;
  REQUIRE_THROWS_WITH(f.validate(), Catch::Contains("newton"));
  f = PhongFormat{};
  f.log_frac_bits = f.cos_frac;
  REQUIRE_THROWS_WITH(f.validate(), Catch::Contains("log_frac_bits"));
  f = PhongFormat{};
  f.exp_frac_bits = f.log_bits;
  REQUIRE_THROWS_WITH(f.validate(), Catch::Contains("exp_frac_bits"));
  REQUIRE_THROWS_AS(PhongModel(f), std::invalid_argument);
}

TEST_CASE("phong: ROM words against their closed forms", "[phong][rom]") {
  const PhongFormat f = GENERATE(PhongFormat{}, PhongFormat::preset(128), PhongFormat::preset(64));
  const auto rs = phong_rsqrt_rom(f);
  REQUIRE(rs.size() == static_cast<size_t>(3 << (f.rsqrt_addr_bits - 2)));
  for (size_t j = 0; j < rs.size(); ++j) {
    const double x = 1.0 + (j + 0.5) * 3.0 / static_cast<double>(rs.size());
    REQUIRE_THAT(static_cast<double>(rs[j]), WithinAbs(std::ldexp(1.0, f.norm_bits) / std::sqrt(x), 0.5));
    if (j) REQUIRE(rs[j] < rs[j - 1]);
  }
  const auto lg = phong_log_rom(f);
  const int ldb = f.log_delta_bits();
  REQUIRE(lg.size() == static_cast<size_t>(1) << f.log_addr_bits);
  REQUIRE((lg[0] >> ldb) == 0);
  for (size_t j = 0; j < lg.size(); ++j) {
    const uint64_t v = lg[j] >> ldb, dv = lg[j] & ((uint64_t{1} << ldb) - 1);
    const double x = 1.0 + std::ldexp(static_cast<double>(j), -f.log_addr_bits);
    REQUIRE_THAT(static_cast<double>(v), WithinAbs(std::ldexp(std::log2(x), f.log_bits), 0.5));
    const uint64_t next = j + 1 < lg.size() ? lg[j + 1] >> ldb : uint64_t{1} << f.log_bits;
    REQUIRE(v + dv == next);  // continuous: the step reaches the next word
  }
  const auto ex = phong_exp_rom(f);
  const int edb = f.exp_delta_bits();
  REQUIRE((ex[0] >> edb) == uint64_t{1} << f.exp_bits);
  for (size_t j = 0; j < ex.size(); ++j) {
    const uint64_t u = ex[j] >> edb, du = ex[j] & ((uint64_t{1} << edb) - 1);
    REQUIRE_THAT(static_cast<double>(u),
                 WithinAbs(std::ldexp(std::exp2(-std::ldexp(static_cast<double>(j), -f.exp_addr_bits)), f.exp_bits), 0.5));
    const uint64_t next = j + 1 < ex.size() ? ex[j + 1] >> edb : uint64_t{1} << (f.exp_bits - 1);
    REQUIRE(u - du == next);
  }
}

TEST_CASE("phong: N = H gives scale (cos = 1) within the budget at every n", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 20; ++k) {
    const glm::dvec3 v = random_unit(rng);
    const GeoSpan s0 = span_of(f, v, v, v, v, 1, 0, 1.5);
    for (int n : {1, 2, 17, 64, 128, 999, 1000}) {
      GeoSpan s = s0;
      s.n = static_cast<uint32_t>(n);
      REQUIRE(std::abs(static_cast<double>(m.pixel(s, 0)) - s.scale) <= 1e-3 * s.scale + 1.0);
    }
  }
}

TEST_CASE("phong: the interpolation is exact at l = 2047 (operands = floor of the exact lerp)", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(11);
  const GeoSpan s = span_of(f, random_unit(rng), random_unit(rng), random_unit(rng), random_unit(rng), 10, 2047);
  const int drop = f.acc_bits() - f.op_bits;
  for (int i : {0, 1, 2, 1023, 1024, 2045, 2046, 2047}) {
    const PhongTrace t = m.trace(s, i);
    for (int c = 0; c < 3; ++c) {
      // l = 2047 = 2^11 - 1: L = l, no shift; l N_i = (l - i) N1 + i N2 exactly.
      const int64_t an = int64_t{2047 - i} * s.n1[c] + int64_t{i} * s.n2[c];
      const int64_t bn = int64_t{2047 - i} * s.h1[c] + int64_t{i} * s.he[c];
      REQUIRE(t.a[c] == (an >> drop));
      REQUIRE(t.b[c] == (bn >> drop));
    }
  }
}

TEST_CASE("phong: a span and its reverse give the same pixels in reverse order", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(5);
  for (int k = 0; k < 30; ++k) {
    const GeoSpan s = random_span(f, rng, 1000);
    const GeoSpan r = reversed(s);
    for (int i = 0; i <= static_cast<int>(s.len); i += 1 + static_cast<int>(s.len) / 50)
      REQUIRE(m.pixel(s, i) == m.pixel(r, static_cast<int>(s.len) - i));
  }
}

TEST_CASE("phong: swapping N and H does not change a pixel", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(6);
  for (int k = 0; k < 30; ++k) {
    GeoSpan s = random_span(f, rng, 1000);
    GeoSpan w = s;
    std::swap(w.n1, w.h1);
    std::swap(w.n2, w.he);
    for (int i = 0; i <= static_cast<int>(s.len); i += 1 + static_cast<int>(s.len) / 50) REQUIRE(m.pixel(s, i) == m.pixel(w, i));
  }
}

TEST_CASE("phong: a pixel never grows with n", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(8);
  for (int k = 0; k < 20; ++k) {
    GeoSpan s = random_span(f, rng, 1000);
    const int i = static_cast<int>(s.len / 2);
    uint32_t prev = 0xffffffffU;
    for (uint32_t n = 1; n <= 1000; ++n) {
      s.n = n;
      const uint32_t p = m.pixel(s, i);
      REQUIRE(p <= prev);
      prev = p;
    }
  }
}

TEST_CASE("phong: the stream gives l + 1 pixels per span with its tag and last on pixel l", "[phong]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(9);
  std::vector<GeoSpan> spans;
  for (int k = 0; k < 5; ++k) {
    GeoSpan s = random_span(f, rng, 1000);
    s.len = static_cast<uint32_t>(k * 3);
    s.tag = 0xabcd0000U + static_cast<uint32_t>(k);
    spans.push_back(s);
  }
  const auto px = m.stream(spans);
  size_t at = 0;
  for (const GeoSpan& s : spans)
    for (uint32_t i = 0; i <= s.len; ++i, ++at) {
      REQUIRE(px[at].last == (i == s.len));
      REQUIRE(px[at].tag == (s.tag & 0xffffU));
      REQUIRE(px[at].intensity == m.pixel(s, static_cast<int>(i)));
    }
  REQUIRE(at == px.size());
}

TEST_CASE("phong hard case: n = 0 and n > 1000 give 0", "[phong][hard]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(12);
  GeoSpan s = random_span(f, rng, 10);
  s.n1 = s.h1;  // cos = 1 at pixel 0
  for (uint32_t n : {0U, 1001U, 1023U}) {
    s.n = n;
    for (int i = 0; i <= static_cast<int>(s.len); i += 1 + static_cast<int>(s.len) / 20) REQUIRE(m.pixel(s, i) == 0);
  }
}

TEST_CASE("phong hard case: N.H <= 0 gives 0", "[phong][hard]") {
  const PhongFormat f;
  const PhongModel m(f);
  const glm::dvec3 x(1, 0, 0), y(0, 1, 0);
  REQUIRE(m.pixel(span_of(f, -x, -x, x, x, 1, 0), 0) == 0);  // opposite
  REQUIRE(m.pixel(span_of(f, y, y, x, x, 1, 0), 0) == 0);    // perpendicular: N.H = 0 exactly
  // A span that turns from facing H to facing away: 0 exactly where the exact cosine is <= 0.
  const GeoSpan s = span_of(f, x, -x + 0.1 * y, x, x, 1, 100);
  for (int i = 0; i <= 100; ++i) {
    double c = 0.0;
    phong_exact(s, f, i, &c);
    if (c <= 0.0) REQUIRE(m.pixel(s, i) == 0);
  }
}

TEST_CASE("phong hard case: a zero vector zeroes every pixel of its span", "[phong][hard]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(13);
  for (int which = 0; which < 4; ++which) {
    GeoSpan s = random_span(f, rng, 10);
    s.n1 = s.h1;
    s.len = 20;
    GeoVec* v[] = {&s.n1, &s.n2, &s.h1, &s.he};
    *v[which] = GeoVec{0, 0, 0};
    for (int i = 0; i <= 20; ++i) REQUIRE(m.pixel(s, i) == 0);
  }
  // N1 = -N2: the interpolated normal passes through zero at i = l/2.
  const glm::dvec3 x(1, 0, 0);
  const GeoSpan s = span_of(f, x, -x, x, x, 1, 10);
  REQUIRE(m.pixel(s, 5) == 0);
  REQUIRE(m.pixel(s, 0) > 0);
}

TEST_CASE("phong hard case: l = 0 is pixel 0 of N1, H1 only", "[phong][hard]") {
  const PhongFormat f;
  const PhongModel m(f);
  std::mt19937_64 rng(14);
  for (int k = 0; k < 50; ++k) {
    GeoSpan s = random_span(f, rng, 1000);
    s.len = 0;
    GeoSpan t = s;
    t.n2 = GeoVec{1, 2, 3};  // not read when l = 0
    t.he = GeoVec{-3, 2, 1};
    REQUIRE(m.pixel(s, 0) == m.pixel(t, 0));
    check_budget(m, s);
  }
  REQUIRE_THROWS_AS(m.pixel(GeoSpan{}, 1), std::out_of_range);
}

TEST_CASE("phong hard case: constant H ignores He and meets the budget", "[phong][hard]") {
  PhongFormat f;
  f.const_h = true;
  const PhongModel m(f);
  std::mt19937_64 rng(15);
  for (int k = 0; k < 20; ++k) {
    GeoSpan s = random_span(f, rng, 1000);
    GeoSpan t = s;
    t.he = GeoVec{0, 0, 0};
    for (int i = 0; i <= static_cast<int>(s.len); i += 1 + static_cast<int>(s.len) / 30) REQUIRE(m.pixel(s, i) == m.pixel(t, i));
    check_budget(m, s);
  }
}

TEST_CASE("phong: random spans meet the budget against double per-pixel Phong", "[phong]") {
  const int n_max = GENERATE(1000, 128, 64);
  const PhongFormat f = PhongFormat::preset(n_max);
  const PhongModel m(f);
  std::mt19937_64 rng(static_cast<uint64_t>(n_max));
  for (int k = 0; k < 40; ++k) check_budget(m, random_span(f, rng, n_max));
}

TEST_CASE("phong: the sweep's error per n meets the budget (n = 1, 2, 1000 and the preset ranges)", "[phong]") {
  const auto [n_max, n] = GENERATE(table<int, int>({{1000, 1}, {1000, 2}, {1000, 500}, {1000, 1000}, {128, 128},
                                                     {64, 1}, {64, 64}}));
  const PhongModel m(PhongFormat::preset(n_max));
  const PhongError e = phong_error(m, n, 3);
  INFO("n_max=" << n_max << " n=" << n << " rel " << e.rel_lsb << " abs " << e.abs_lsb);
  REQUIRE(e.epicenter_pixels > 100);
  REQUIRE(e.meets());
  // The sweep reaches the budget's scale: the error is not trivially 0 at large n.
  if (n == n_max && n > 1) REQUIRE(e.rel_raw > 1e-4);
}

TEST_CASE("phong: phong_exact agrees with phong_truth for exactly unit end vectors", "[phong]") {
  const PhongFormat f;
  const double one = std::ldexp(1.0, f.vec_frac);
  GeoSpan s;
  s.n1 = {static_cast<int32_t>(one), 0, 0};
  s.n2 = {0, static_cast<int32_t>(one), 0};
  s.h1 = {0, 0, static_cast<int32_t>(one)};
  s.he = {static_cast<int32_t>(one), 0, 0};
  s.n = 3;
  s.len = 7;
  s.scale = 1U << f.c_frac;
  const ScanlineInput in = geo_input(s, geo_format(f), c_format(f));
  for (int i = 0; i <= 7; ++i) REQUIRE_THAT(phong_exact(s, f, i), WithinAbs(phong_truth(in, i), 1e-15));
}

TEST_CASE("phong: the error budgets of docs/metrics.md#budgets", "[phong][budget]") {
  REQUIRE(std::string(PixelBudget::named("b2").name) == "b2");
  REQUIRE_THROWS_WITH(PixelBudget::named("b5"), Catch::Contains("b1, b2, b3, b4"));
  PhongError e;
  e.rel_lsb = 5e-3;  // over B1's 0.10 %, within B3's 1 %
  e.abs_lsb = 1e-3;
  e.abs_raw = 1.5e-3;  // within B2's 2^-9 = 1.95e-3
  REQUIRE_FALSE(e.meets(PixelBudget::b1()));
  REQUIRE(e.meets(PixelBudget::b3()));
  REQUIRE(e.meets(PixelBudget::b2()));
  REQUIRE_FALSE(e.meets(PixelBudget::b2(), 0.5));  // held to half of it
  REQUIRE_FALSE(e.meets(PixelBudget::b4()));        // B4's 2^-11 = 4.88e-4 (a 10-bit display)
  e.abs_raw = 4.8e-4;
  REQUIRE(e.meets(PixelBudget::named("b4")));
  e.abs_raw = 2.5e-3;
  REQUIRE_FALSE(e.meets(PixelBudget::b2()));
  // The sweep measures the raw absolute error too: at least the allowance-free absolute one.
  const PhongModel m(PhongFormat{});
  const PhongError s = phong_error(m, 64, 1);
  REQUIRE(s.abs_raw >= s.abs_lsb);
  REQUIRE(s.abs_raw <= s.abs_lsb + std::ldexp(1.0, -m.format().c_frac) + 1e-12);
}
