// SPDX-License-Identifier: Apache-2.0
// The blended datapath of the golden model (Format::blend, docs/display_exact.md#datapath): its
// decoder table and bank domains against closed forms, every blended pixel against the weighted
// sum rounded a second way, each ROM 12 read against cos^k in double, and the single-bank builds
// unchanged by the new fields.
#include "blend.hpp"
#include "blend_rom.hpp"
#include "device_error.hpp"
#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

using namespace specular;
using device::DeviceModel;
using device::Format;
using device::Registers;

namespace {

const std::vector<int> kSet{1, 2, 3, 4, 8, 16, 64, 256, 1024};

// Maclaurin coefficients for every n, the minimax fit for the n a test measures.
std::vector<BlendCoef> table_with(const std::vector<int>& banks, std::initializer_list<int> fitted) {
  std::vector<BlendCoef> t;
  for (int n = 1; n <= 1000; ++n) {
    int k1 = 0, k2 = 0;
    blend_banks(banks, n, k1, k2);
    t.push_back(blend_maclaurin(n, k1, k2));
  }
  for (int n : fitted) t[n - 1] = blend_minimax(n, t[n - 1].k1, t[n - 1].k2);
  return t;
}

}  // namespace

TEST_CASE("blend: decoder table and bank domains from their closed forms", "[golden][blend]") {
  CHECK(derive_blend_bank_max_n({1, 2, 4, 16, 64, 256, 1024}) == std::vector<int>{1, 3, 15, 63, 255, 1000});
  CHECK(derive_blend_bank_max_n({1, 2, 3, 4, 8, 16, 256}) == std::vector<int>{1, 2, 3, 7, 15, 255, 1000});
  REQUIRE_THROWS_WITH(derive_blend_bank_max_n({2, 4}), Catch::Contains("start at k = 1"));
  // The largest s with cos^k(pi/2 2^-s) <= 2^-24 (0 when none), from k ln cos in double here.
  const std::vector<int> banks{1, 2, 4, 16, 64, 256, 1024};
  const std::vector<int> shift = derive_bank_shift(banks);
  auto log_end = [&](size_t j, int s) {
    return banks[j] * std::log(std::cos(std::numbers::pi / std::pow(2.0, s + 1)));
  };
  for (size_t j = 0; j < banks.size(); ++j) {
    CHECK(log_end(j, shift[j] + 1) > -24 * std::log(2.0));  // one more halving would cut the lobe
    if (shift[j] > 0) CHECK(log_end(j, shift[j]) <= -24 * std::log(2.0));
  }
  CHECK(shift == std::vector<int>{0, 0, 0, 0, 1, 2, 3});
}

TEST_CASE("blend: a format without blend and with zero shifts is the single-bank build, unchanged",
          "[golden][blend]") {
  Format f;
  Format g = f;
  g.bank_shift.assign(f.banks.size(), 0);
  REQUIRE(cos_rom_image(g) == cos_rom_image(f));
  const CoefSpec spec = parse_coef_spec("minimax");
  REQUIRE(coef_rom_image(g, spec) == coef_rom_image(f, spec));
  REQUIRE_THROWS_WITH(DeviceModel(blend_format(f, kSet), coef_rom_image(f, spec), cos_rom_image(f)),
                      Catch::Contains("blend mode needs"));
}

TEST_CASE("blend: every pixel is the weighted sum of its two reads, rounded half up", "[golden][blend]") {
  const Format f = blend_format(Format{}, kSet);
  const DeviceModel dm = blend_device_model(f, table_with(kSet, {3, 5, 20, 300}));
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> pick_n(1, 1000);
  std::uniform_real_distribution<double> angle(-1.7, 1.7);
  const double d = std::ldexp(1.0, f.cos_data_bits);
  int blended = 0;
  for (int s = 0; s < 400; ++s) {
    Registers r;
    r.n = static_cast<uint32_t>(pick_n(rng));
    r.c = static_cast<uint32_t>(rng() % 65536);
    r.psi0 = device::quantize_angle(angle(rng) / std::sqrt(static_cast<double>(r.n)), f);
    r.dpsi = device::quantize_angle(0.001, f);
    r.len = 3;
    for (int i = 0; i <= 3; ++i) {
      const device::PixelTrace t = dm.trace(r, i);
      if (t.far) {
        CHECK(t.intensity == 0u);
        continue;
      }
      ++blended;
      REQUIRE(t.bank2 == std::min(t.bank + 1, static_cast<int>(kSet.size()) - 1));
      // (c1 (2^W - w) + c2 w) / 2^W rounded half up, exactly in integers.
      const int64_t W = int64_t{1} << f.weight_bits;
      const int64_t num = static_cast<int64_t>(t.cosk) * (W - t.weight) + static_cast<int64_t>(t.cosk2) * t.weight;
      const int64_t q = (num + W / 2) / W - ((num + W / 2) % W < 0 ? 1 : 0);
      REQUIRE(static_cast<int64_t>(t.blended) == q);
      REQUIRE(t.intensity == static_cast<uint32_t>((static_cast<uint64_t>(r.c) * t.blended + (1ULL << 17)) >> 18));
      // Each read is cos^k(a |psi|) of its bank to the table's accuracy (interpolation and rounding:
      // within 2^-11 at 256 entries per domain), 0 past the domain.
      const double psi = std::abs(device::angle_value(t.psi, f));
      for (int which = 0; which < 2; ++which) {
        const int j = which == 0 ? t.bank : t.bank2;
        const uint32_t coef = which == 0 ? t.coef : t.coef2;
        const uint32_t got = which == 0 ? t.cosk : t.cosk2;
        const double a = device::coef_value(coef, f) / std::ldexp(1.0, f.shift_of(j));
        const double z = a * psi;
        const bool inside = z * std::ldexp(1.0, f.shift_of(j)) < std::numbers::pi / 2;
        const double want = inside ? std::pow(std::cos(z), kSet[j]) : 0.0;
        CHECK(std::abs(got / d - want) < std::ldexp(1.0, -11));
      }
    }
  }
  CHECK(blended > 500);
}

TEST_CASE("blend: the device error of the default widths is the fit's plus quantization", "[golden][blend]") {
  const Format f = blend_format(Format{}, kSet);
  const std::vector<BlendCoef> t = table_with(kSet, {3, 5, 7, 20, 100, 1000});
  const DeviceModel dm = blend_device_model(f, t);
  const int n = GENERATE(3, 5, 7, 20, 100, 1000);
  const DeviceError e = device_error(dm, n);
  // The fit's own error plus a few output LSBs of rounding (2^-15 each).
  CHECK(e.max_abs_lobe <= t[n - 1].max_abs + 4 * std::ldexp(1.0, -15));
  CHECK(e.max_abs_lobe <= std::ldexp(1.0, -11));  // B4
  CHECK(e.max_srgb8_codes <= 2);
}

TEST_CASE("blend: ROM 9 fields that do not fit are refused naming n", "[golden][blend]") {
  Format f = blend_format(Format{}, kSet);
  f.coef_bits = 12;
  f.coef_frac = 12;  // no integer bit: a * 2^s * 2/pi >= 1 does not fit
  REQUIRE_THROWS_WITH(blend_device_model(f, table_with(kSet, {})), Catch::Contains("blend ROM 9 entry n = "));
}

TEST_CASE("srgb8_code: the encoding's closed form at its ends and its knee", "[golden][blend]") {
  CHECK(srgb8_code(0.0) == 0);
  CHECK(srgb8_code(1.0) == 255);
  CHECK(srgb8_code(2.0) == 255);
  CHECK(srgb8_code(0.0031308) == 10);   // 255 * 12.92 * 0.0031308 = 10.31
  CHECK(srgb8_code(0.5) == 188);        // 255 * (1.055 * 0.5^(1/2.4) - 0.055) = 187.5 + ...
}
