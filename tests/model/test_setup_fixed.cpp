// SPDX-License-Identifier: Apache-2.0
// The fixed-point setup (model/host/setup_fixed.hpp, docs/setup_hw.md#the-setup)
// against independent references: its primitives against long double mathematics, and the
// whole setup against the contract of docs/setup_hw.md#the-contract (the scalar double setup on
// the exact values under the hardware's stated rule, host::check_contract): on the hard cases,
// near-opposite normal and halfway codes, tiny chords at the top of C and random spans.
// SPECULAR_SETUP_FIXED_SPANS=N runs N random spans instead of 20,000 (the long option).
#include "setup_fixed.hpp"

#include "setup_contract.hpp"
#include "geo_cases.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace specular;
namespace hf = specular::host::fixed;
using device::GeoSpan;
using geo_cases::kFmt;
using geo_cases::kGeo;

namespace {

long double q(int64_t code, int frac) { return std::ldexp(static_cast<long double>(code), -frac); }

host::ContractCheck check(const GeoSpan& g, const hf::Result& r) {
  return host::check_contract(g, r.status, {r.trace.opposite_normals, r.trace.flat, r.trace.opposite_halfway}, r.span.reg,
                              kGeo, kFmt);
}

}  // namespace

TEST_CASE("fixed setup: rsqrt, normalize and block normalization against long double", "[setup_fixed]") {
  const int frac = GENERATE(20, 26, 30);
  const hf::Widths w{frac};
  const int b = w.rsqrt_in_bits();
  long double worst_r = 0, worst_u = 0;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const uint64_t m = (uint64_t{1} << (b - 2)) + rng() % (3 * (uint64_t{1} << (b - 2)));
    const long double want = 1.0L / std::sqrt(std::ldexp(static_cast<long double>(m), -b));
    worst_r = std::max(worst_r, std::abs(q(hf::rsqrt(m, w), w.rsqrt_frac()) / want - 1.0L));
  }
  for (int i = 0; i < 100000; ++i) {
    hf::Vec v{};
    const int bits = 1 + static_cast<int>(rng() % (i % 2 ? 24 : 60));
    for (auto& c : v) c = static_cast<int64_t>(rng() % (uint64_t{1} << bits)) - (int64_t{1} << (bits - 1));
    const hf::Vec u = hf::normalize(v, w);
    long double len = 0;
    for (auto c : v) len += static_cast<long double>(c) * c;
    len = std::sqrt(len);
    for (size_t k = 0; k < 3; ++k)
      if (len > 0) worst_u = std::max(worst_u, std::abs(q(u[k], frac) - v[k] / len));
  }
  INFO("F " << frac << ": rsqrt relative " << static_cast<double>(worst_r) << ", unit component " << static_cast<double>(worst_u));
  CHECK(worst_r < std::ldexp(1.0L, -(frac + 1)));  // 1 NR step from the interpolated seed (~2^-34 before rounding)
  CHECK(worst_u < std::ldexp(1.0L, -frac));
  CHECK(hf::normalize({0, 0, 0}, w) == hf::Vec{0, 0, 0});
  CHECK_THROWS(hf::rsqrt(uint64_t{1} << (b - 3), w));
  // Block normalization: the largest magnitude lands in [2^(bits-1), 2^bits], the shift is returned.
  std::array<hf::i128, 3> v{5, -1000, 3};
  CHECK(hf::block_normalize(v, 4) == 6);  // 1000 / 2^6 = 15.6 -> 16, in [2^3, 2^4]
  CHECK(v == std::array<hf::i128, 3>{0, -16, 0});
  std::array<hf::i128, 3> s{1, 0, -3};
  CHECK(hf::block_normalize(s, 10) == -8);
  CHECK(s == std::array<hf::i128, 3>{256, 0, -768});
  CHECK_THROWS_WITH(hf::check_widths(hf::Widths{27}), Catch::Contains("even and in 20..30, got 27"));
}

TEST_CASE("fixed setup: the CORDIC angle against atan2", "[setup_fixed]") {
  const int frac = GENERATE(23, 29, 33);
  const int iters = frac - 1, bits = frac + 5;
  long double worst = 0;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<long double> ang(-std::numbers::pi_v<long double>, std::numbers::pi_v<long double>);
  for (int i = 0; i < 100000; ++i) {
    const long double t = ang(rng), r = std::ldexp(1.0L, -static_cast<int>(rng() % 12)) * (1.0L + (rng() % 1000) / 1000.0L);
    const auto x = static_cast<int64_t>(std::llround(std::ldexp(r * std::cos(t), frac)));
    const auto y = static_cast<int64_t>(std::llround(std::ldexp(r * std::sin(t), frac)));
    const int64_t a = hf::cordic_angle(x, y, frac, iters, bits);
    worst = std::max(worst, r * std::abs(q(a, frac) - std::atan2(q(y, frac), q(x, frac))));
  }
  INFO("frac " << frac << ": atan2 within " << static_cast<double>(worst) << " rad |v|");
  CHECK(worst < std::ldexp(1.0L, -(frac - 4)));
  CHECK(hf::pi_word(frac) == std::llround(std::ldexp(std::numbers::pi_v<long double>, frac)));
  for (int i = 0; i < iters; ++i)
    CHECK(std::abs(q(hf::atan_word(i, frac), frac) - std::atan(std::ldexp(1.0L, -i))) <= std::ldexp(0.5L, -frac) * 1.0001L);
  CHECK_THROWS(hf::cordic_angle(int64_t{1} << (bits - 2), int64_t{1} << (bits - 2), frac, iters, bits));
}

TEST_CASE("fixed setup: every hard and near-degenerate case meets the contract", "[setup_fixed]") {
  std::vector<GeoSpan> spans = geo_cases::near_degenerate_spans();
  std::vector<std::string> names(spans.size(), "near-degenerate");
  for (const auto& h : geo_cases::hard_cases()) spans.push_back(h.g), names.push_back(h.name);
  std::vector<int> seen(5, 0);
  double worst = 0;
  int bands = 0;
  for (size_t i = 0; i < spans.size(); ++i) {
    const GeoSpan& g = spans[i];
    const hf::Result r = hf::setup_fixed(g, kGeo, kFmt);
    const host::ContractCheck c = check(g, r);
    INFO(i << " " << names[i] << ": status " << to_string(r.status) << " / " << to_string(c.ref_status) << ", flat "
           << r.trace.flat << " / " << c.ref_flat << "; C " << r.span.reg.c << " / " << c.ref.c << ", psi0 "
           << r.span.reg.psi0 << " / " << c.ref.psi0 << ", dpsi " << r.span.reg.dpsi << " / " << c.ref.dpsi << "; worst "
           << c.pixels.worst);
    seen.at(static_cast<size_t>(r.status))++;
    CHECK(c.decisions_equal);
    CHECK(c.pixels.ok());
    CHECK(r.span.tag == g.tag);
    worst = std::max(worst, c.pixels.worst);
    bands += c.in_band;
  }
  for (int s : seen) CHECK(s > 0);
  WARN("fixed setup, " << spans.size() << " hard and near-degenerate spans: worst " << worst << " of the allowance, "
                      << bands << " decisions in a guard band");
}

TEST_CASE("fixed setup meets the contract on random spans", "[setup_fixed]") {
  const char* env = std::getenv("SPECULAR_SETUP_FIXED_SPANS");
  const size_t total = env ? std::strtoull(env, nullptr, 10) : 20000;
  const size_t chunk = 1 << 16;
  size_t spans = 0, diffs = 0, fails = 0, bands = 0;
  double worst = 0, lsb = 0;
  for (size_t done = 0; done < total; done += chunk) {
    for (const GeoSpan& g : geo_cases::random_geo_spans(std::min(chunk, total - done), 20261205 + done)) {
      ++spans;
      const hf::Result r = hf::setup_fixed(g, kGeo, kFmt);
      const host::ContractCheck c = check(g, r);
      diffs += !c.decisions_equal;
      fails += !c.pixels.ok();
      bands += static_cast<size_t>(c.in_band);
      worst = std::max(worst, c.pixels.worst), lsb = std::max(lsb, c.pixels.max_abs_lsb);
    }
  }
  CHECK(spans == total);
  CHECK(diffs == 0);
  CHECK(fails == 0);
  WARN("fixed setup, " << spans << " random spans: worst " << worst << " of the allowance, max " << lsb << " LSB, "
                      << bands << " decisions in a guard band");
}

TEST_CASE("fixed setup: the flat path meets the contract on one-pixel and flat spans", "[setup_fixed]") {
  std::vector<GeoSpan> spans = geo_cases::random_geo_spans(20000, 4242);
  for (size_t i = 0; i < spans.size(); ++i) {
    if (i % 2 == 0) spans[i].len = 0;  // one-pixel spans of any geometry
    else spans[i].n2 = spans[i].n1, spans[i].he = spans[i].h1;  // flat spans of any length
  }
  for (const auto& h : geo_cases::hard_cases()) spans.push_back(h.g);
  for (const auto& g : geo_cases::near_degenerate_spans()) spans.push_back(g);
  size_t taken = 0, fails = 0, diffs = 0, same_c = 0, flat_gen = 0;
  double worst = 0;
  for (const GeoSpan& g : spans) {
    if (!hf::takes_flat_path(g)) continue;
    ++taken;
    const hf::Result r = hf::setup_fixed_flat(g, kGeo, kFmt);
    const host::ContractCheck c = check(g, r);
    fails += !c.pixels.ok();
    diffs += !c.decisions_equal;
    worst = std::max(worst, c.pixels.worst);
    CHECK(r.span.reg.dpsi == 0);
    CHECK(r.span.reg.psi0 == 0);
    // The general path on the same span gives the same C (the same cos t1, A = |cos t1|) when cos t1 > 0.
    const hf::Result gen = hf::setup_fixed(g, kGeo, kFmt);
    if (r.trace.cos_t1 > 0 && gen.trace.flat) ++flat_gen, same_c += gen.span.reg.c == r.span.reg.c;
  }
  INFO(taken << " spans on the flat path");
  CHECK(taken >= 20000);
  CHECK(fails == 0);
  CHECK(diffs == 0);
  CHECK(flat_gen > 5000);
  CHECK(same_c == flat_gen);
  WARN("fixed setup flat path, " << taken << " spans: worst " << worst << " of the allowance; C equal to the general path's on "
                          << same_c << " flat spans with cos t1 > 0");
}
