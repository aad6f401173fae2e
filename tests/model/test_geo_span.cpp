// SPDX-License-Identifier: Apache-2.0
// The geometry span interface's codes (model/device/geo_span.hpp,
// docs/interfaces.md#geometry-span-interface): quantization, exact values, packing.
#include "geo_span.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace specular;
using device::GeoFormat;
using device::GeoVec;

TEST_CASE("geo_span: components round to the nearest 2^-VecFrac, ties away from zero, and saturate",
          "[geo_span]") {
  const GeoFormat g;  // 18 bits, 16 fraction bits: [-2, 2 - 2^-16]
  bool sat = true;
  // 0.5 + 1.5 * 2^-16 lies between codes 32769 and 32770: the tie goes away from zero.
  GeoVec v = device::quantize_vec({0.5, -0.25, 0.5 + 1.5 / 65536.0}, g, &sat);
  CHECK(v == GeoVec{32768, -16384, 32770});
  CHECK_FALSE(sat);
  v = device::quantize_vec({-0.5 - 1.5 / 65536.0, 1.0 / 3.0, -1.0 / 3.0}, g, &sat);
  CHECK(v == GeoVec{-32770, 21845, -21845});  // 65536 / 3 = 21845.33
  CHECK_FALSE(sat);
  v = device::quantize_vec({2.0, -2.0, -3.0}, g, &sat);
  CHECK(v == GeoVec{131071, -131072, -131072});
  CHECK(sat);
  v = device::quantize_vec({std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0}, g, &sat);
  CHECK(v == GeoVec{0, 0, 65536});
  CHECK(sat);
}

TEST_CASE("geo_span: a code's value is exact and quantizes back to itself", "[geo_span]") {
  const GeoFormat g;
  std::mt19937 rng(20261203);
  std::uniform_int_distribution<int32_t> code(static_cast<int32_t>(g.vec_min()), static_cast<int32_t>(g.vec_max()));
  for (int k = 0; k < 10000; ++k) {
    const GeoVec v{code(rng), code(rng), code(rng)};
    const glm::dvec3 x = device::vec_value(v, g);
    for (int i = 0; i < 3; ++i) CHECK(x[i] * 65536.0 == static_cast<double>(v[static_cast<size_t>(i)]));
    bool sat = true;
    CHECK(device::quantize_vec(x, g, &sat) == v);
    CHECK_FALSE(sat);
  }
}

TEST_CASE("geo_span: packing is {z, y, x}, x in the low bits, two's complement per component", "[geo_span]") {
  const GeoFormat g;
  // x = -1 (all 18 bits set), y = 1, z = -2^17 (only the top bit set).
  const GeoVec v{-1, 1, -131072};
  const uint64_t want = (uint64_t{1} << 53) | (uint64_t{1} << 18) | ((uint64_t{1} << 18) - 1);
  CHECK(device::pack_vec(v, g) == want);
  CHECK(device::unpack_vec(want, g) == v);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int32_t> code(static_cast<int32_t>(g.vec_min()), static_cast<int32_t>(g.vec_max()));
  for (int k = 0; k < 10000; ++k) {
    const GeoVec r{code(rng), code(rng), code(rng)};
    const uint64_t bits = device::pack_vec(r, g);
    CHECK(bits >> g.packed_bits() == 0U);
    CHECK(device::unpack_vec(bits, g) == r);
  }
  GeoFormat wide;
  wide.vec_bits = 22;
  CHECK_THROWS_AS(device::pack_vec(v, wide), std::invalid_argument);
  CHECK_THROWS_AS(device::unpack_vec(0, wide), std::invalid_argument);
}

TEST_CASE("geo_span: a scanline input to a geometry span and back", "[geo_span]") {
  const GeoFormat g;
  const device::Format f;
  ScanlineInput in;
  in.n1 = {0.0, 0.6, 0.8};
  in.n2 = {0.0, -0.6, 0.8};
  in.h1 = {0.28, 0.0, 0.96};
  in.he = {0.28, 0.0, 0.96};
  in.is = 0.8;
  in.ks = 0.5;
  in.norm = 1.5;  // scale 0.6
  in.n = 37.4;
  in.l = 5000;  // beyond the counter: clamped to 2047
  const device::GeoSpan s = device::quantize_geo(in, g, f, 0x12345);
  CHECK(s.n == 37U);
  CHECK(s.len == 2047U);
  CHECK(s.scale == static_cast<uint32_t>(std::lround(0.6 * 32768.0)));
  CHECK(s.tag == 0x2345U);  // TagBits = 16
  const ScanlineInput back = device::geo_input(s, g, f);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::abs(back.n1[i] - in.n1[i]) <= 0.5 / 65536.0);
    CHECK(std::abs(back.h1[i] - in.h1[i]) <= 0.5 / 65536.0);
  }
  CHECK(back.is == static_cast<double>(s.scale) / 32768.0);
  CHECK(back.ks == 1.0);
  CHECK(back.norm == 1.0);
  CHECK(back.n == 37.0);
  CHECK(back.l == 2047);
}
