// SPDX-License-Identifier: Apache-2.0
// ROM 9 (coefficients) and ROM 12 (cos^k), both builds, entry by entry. The RTL ROMs load
// the committed hex files with $readmemh (paths relative to the repository root, the
// working directory of this test). ROM 12 is checked against values computed here from
// cos^k in long double (independent of the generator), against the generator's image
// (model/device/rom_image.hpp), and, interpolated, against the linear interpolation of the true
// cos^k between the two neighbouring entries. Reads are streamed one per clock and checked
// their latency later (pipe_stream.hpp), also with random stalls.
#include "Vcoef_rom_maclaurin.h"
#include "Vcoef_rom_minimax.h"
#include "Vcos_k_rom.h"
#include "Vcos_k_rom_patent.h"
#include "Vpipeline_single_specular_pipeline.h"
#include "Vpipeline_patent_specular_pipeline.h"
#include "pipe_stream.hpp"
#include "rtl_harness.hpp"

#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using specular::rtl_test::run_stream;
using specular::rtl_test::tick;

namespace {

constexpr long double kPi = std::numbers::pi_v<long double>;

template <class Rom>
void check_coef_rom(Rom& dut, const std::vector<uint32_t>& image) {
  REQUIRE(image.size() == 1024);
  int mismatches = 0;
  for (unsigned n = 0; n < 1024; ++n) {
    dut.n_i = n;
    tick(dut);  // registered read: the word appears after the edge
    if (static_cast<uint32_t>(dut.coef_o) != image[n]) {
      if (++mismatches <= 10) {
        UNSCOPED_INFO("n = " << n << ": rtl " << dut.coef_o << ", generator " << image[n]);
      }
    }
  }
  CHECK(mismatches == 0);
  // en_i low holds the word (ROM 9 is read only when a span is accepted).
  dut.n_i = 1;
  tick(dut);
  const uint32_t w1 = dut.coef_o;
  dut.en_i = 0;
  dut.n_i = 1000;
  tick(dut);
  CHECK(static_cast<uint32_t>(dut.coef_o) == w1);
  dut.en_i = 1;
  tick(dut);
  CHECK(static_cast<uint32_t>(dut.coef_o) == image[1000]);
}

}  // namespace

TEST_CASE("ROM 9 (minimax, 21 bits) matches the generator at all 1024 addresses", "[rtl][rom]") {
  const specular::device::Format f;
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::minimax;
  const auto image = specular::coef_rom_image(f, spec);
  // Independent: unused words are 0; used words are a*2/pi in [1/8, 8) quarter turns per
  // radian (18 fraction bits).
  CHECK(image[0] == 0);
  for (unsigned n = 1001; n < 1024; ++n) CHECK(image[n] == 0);
  for (unsigned n = 1; n <= 1000; ++n) {
    INFO("n = " << n);
    CHECK(image[n] >= (1u << 15));
    CHECK(image[n] < (1u << 21));
  }
  Vcoef_rom_minimax dut;
  dut.en_i = 1;
  check_coef_rom(dut, image);
}

TEST_CASE("ROM 9 (maclaurin, patent build, 18 bits) matches the generator at all 1024 addresses",
          "[rtl][rom][patent]") {
  const specular::device::Format f = specular::device::Format::patent();
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::maclaurin;
  const auto image = specular::coef_rom_image(f, spec);
  // Independent spot checks of the generator itself: a = sqrt(n/k) with the patent's
  // decoder, word = a * 2/pi * 2^15.
  for (unsigned n : {1u, 2u, 3u, 6u, 7u, 100u, 1000u}) {
    const int k = n == 1 ? 1 : n == 2 ? 2 : n <= 6 ? 4 : 16;
    const long double word = std::sqrt(static_cast<long double>(n) / k) * 2 / kPi * 32768.0L;
    INFO("n = " << n);
    CHECK(image[n] == static_cast<uint32_t>(std::llround(word)));
  }
  Vcoef_rom_maclaurin dut;
  dut.en_i = 1;
  check_coef_rom(dut, image);
}

// ------------------------------------------------------------------------------------
// ROM 12, interpolated (single-bank build): 8 banks x 256 words {v (19 bits), d (12 bits)}
// ------------------------------------------------------------------------------------
namespace {

constexpr int kBanks[] = {1, 2, 3, 4, 6, 8, 12, 16};  // k of each bank, bank 0 first
constexpr int kEntries = 256;
constexpr long double kOne = 262144.0L;                // 2^18: cos^k = 1.0
// The configuration's stage count (sim/specular_pipeline.sv).
constexpr int kRom12Latency = static_cast<int>(Vpipeline_single_specular_pipeline::Rom12Stages);

// True cos^k at entry i of bank b, in units of 2^-18 (h = pi/2 / 256).
long double cos_k_true(int bank, int i) {
  if (i >= kEntries) return 0.0L;  // cos(pi/2) = 0
  return std::pow(std::cos(i * (kPi / 2 / kEntries)), kBanks[bank]) * kOne;
}
// The ROM value v: rounded to 18 fraction bits.
int64_t v_ref(int bank, int i) { return std::llround(cos_k_true(bank, i)); }

struct CosItem {
  unsigned bank;  // index, or 8 for "no bank selected" (reads bank 0)
  unsigned addr, frac;
};

std::string check_cos(Vcos_k_rom& m, const CosItem& it) {
  const int b = it.bank < 8 ? static_cast<int>(it.bank) : 0;
  const int i = static_cast<int>(it.addr);
  const int64_t v = v_ref(b, i), d = v - v_ref(b, i + 1);
  const int64_t t = it.frac;
  // Exact formula of the contract, with v and d from long double cos^k.
  const int64_t want = v - (d * t + 2048) / 4096;
  // Linear interpolation of the true cos^k between the neighbours: the table rounding
  // (1/2 LSB, interpolated between the ends) plus the rounding of d t / 2^12 (1/2 LSB).
  const long double w = t / 4096.0L;
  const long double interp = (1 - w) * cos_k_true(b, i) + w * cos_k_true(b, i + 1);
  const int64_t got = m.cosk_o;
  if (got == want && std::fabs(got - interp) <= 1.0L) return {};
  std::ostringstream s;
  s << "bank " << it.bank << " (k = " << kBanks[b] << ") addr " << i << " frac " << t << ": rtl " << got
    << ", formula " << want << ", interpolated cos^k " << static_cast<double>(interp);
  return s.str();
}

int run_cos(Vcos_k_rom& dut, const std::vector<CosItem>& items, bool stalls) {
  std::mt19937 junk(8);
  auto apply = [](Vcos_k_rom& m, const CosItem& it) {
    m.bank_i = it.bank < 8 ? 1u << it.bank : 0u;  // one-hot from decoder 10
    m.addr_i = it.addr;
    m.frac_i = it.frac;
  };
  auto garbage = [&](Vcos_k_rom& m) {
    m.bank_i = 1u << (junk() % 8);
    m.addr_i = junk() % kEntries;
    m.frac_i = junk() % 4096;
  };
  auto any = [](Vcos_k_rom&) { return std::string(); };
  if (stalls) {
    std::mt19937 rng(77);
    auto en = [&](long) { return rng() % 3 != 0; };
    return run_stream(dut, kRom12Latency, items, apply, garbage, check_cos, any, en);
  }
  return run_stream(dut, kRom12Latency, items, apply, garbage, check_cos, any, [](long) { return true; });
}

std::vector<CosItem> random_cos(int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<CosItem> v;
  for (int i = 0; i < count; ++i) v.push_back({static_cast<unsigned>(rng() % 8), static_cast<unsigned>(rng() % kEntries), static_cast<unsigned>(rng() % 4096)});
  return v;
}

}  // namespace

TEST_CASE("ROM 12 (interpolated): every bank and entry, frac 0 / 2048 / 4095", "[rtl][rom]") {
  // Independent anchors of the reference itself: cos^k(0) = 1 exactly (C x 1 exact),
  // cos^2(pi/4) = 1/2, cos^4(pi/4) = 1/4, cos^16(pi/4) = 1/256.
  for (int b = 0; b < 8; ++b) CHECK(v_ref(b, 0) == 262144);
  CHECK(v_ref(1, 128) == 131072);
  CHECK(v_ref(3, 128) == 65536);
  CHECK(v_ref(7, 128) == 1024);
  CHECK(v_ref(0, 255) == std::llround(std::sin(kPi / 512) * kOne));  // cos(pi/2 - h) = sin h

  // The generator's image holds the same {v, d} words (31 bits: v << 12 | d).
  const specular::device::Format f;
  REQUIRE(f.cos_word_bits() == 31);
  const auto image = specular::cos_rom_image(f);
  REQUIRE(image.size() == 8u * kEntries);
  int image_mismatches = 0;
  for (int b = 0; b < 8; ++b)
    for (int i = 0; i < kEntries; ++i) {
      const uint32_t word = image[b * kEntries + i];
      const int64_t v = v_ref(b, i), d = v - v_ref(b, i + 1);
      if (static_cast<int64_t>(word >> 12) != v || static_cast<int64_t>(word & 0xfff) != d) ++image_mismatches;
    }
  CHECK(image_mismatches == 0);

  std::vector<CosItem> items;
  for (unsigned frac : {0u, 2048u, 4095u, 1u})
    for (unsigned b = 0; b < 8; ++b)
      for (unsigned i = 0; i < kEntries; ++i) items.push_back({b, i, frac});
  items.push_back({8, 0, 0});     // no bank selected: bank 0 (zeroed downstream)
  items.push_back({8, 200, 77});
  Vcos_k_rom dut;
  dut.clk_i = 0;
  dut.eval();
  CHECK(run_cos(dut, items, false) == 0);

  // The hand anchors through the RTL: frac 0 reads v.
  const std::pair<CosItem, uint32_t> anchors[] = {
      {{0, 0, 0}, 262144u}, {{7, 0, 0}, 262144u}, {{1, 128, 0}, 131072u}, {{3, 128, 0}, 65536u}};
  for (const auto& [it, want] : anchors) {
    dut.en_i = 1;
    dut.bank_i = 1u << it.bank;
    dut.addr_i = it.addr;
    dut.frac_i = it.frac;
    for (int c = 0; c < kRom12Latency; ++c) tick(dut);
    dut.eval();
    INFO("bank " << it.bank << " addr " << it.addr);
    CHECK(static_cast<uint32_t>(dut.cosk_o) == want);
  }
}

TEST_CASE("ROM 12 (interpolated): random bank, entry and weight streamed one per clock", "[rtl][rom]") {
  Vcos_k_rom dut;
  dut.clk_i = 0;
  dut.eval();
  CHECK(run_cos(dut, random_cos(40000, 12), false) == 0);
}

TEST_CASE("ROM 12 (interpolated) holds every stage while en_i is low (stall)", "[rtl][rom][stall]") {
  Vcos_k_rom dut;
  dut.clk_i = 0;
  dut.eval();
  CHECK(run_cos(dut, random_cos(10000, 13), true) == 0);
}

// ------------------------------------------------------------------------------------
// ROM 12, patent build: 4 banks x 4096 words of 16 bits, direct, saturating at cos^k(0)
// ------------------------------------------------------------------------------------
TEST_CASE("ROM 12 (patent, direct): every bank and entry", "[rtl][rom][patent]") {
  constexpr int k_of[] = {1, 2, 4, 16};
  constexpr int entries = 4096;
  auto want = [&](int b, int i) {
    const long double c = std::pow(std::cos(i * (kPi / 2 / entries)), k_of[b]) * 65536.0L;
    return static_cast<uint32_t>(std::min<long long>(std::llround(c), 0xffff));
  };
  // Anchors: cos^k(0) saturates to 0xffff; cos^2(pi/4) = 1/2, cos^4 = 1/4, cos^16 = 1/256.
  for (int b = 0; b < 4; ++b) CHECK(want(b, 0) == 0xffff);
  CHECK(want(1, 2048) == 0x8000);
  CHECK(want(2, 2048) == 0x4000);
  CHECK(want(3, 2048) == 0x100);
  const auto image = specular::cos_rom_image(specular::device::Format::patent());
  REQUIRE(image.size() == 4u * entries);

  struct Item {
    unsigned bank, addr, frac;
  };
  std::vector<Item> items;
  std::mt19937 rng(5);
  for (unsigned b = 0; b < 4; ++b)
    for (unsigned i = 0; i < entries; ++i) items.push_back({b, i, static_cast<unsigned>(rng() % 4096)});  // frac ignored
  items.push_back({4, 1000, 0});  // no bank selected: bank 0
  std::mt19937 junk(6);
  int image_mismatches = 0;
  auto apply = [](Vcos_k_rom_patent& m, const Item& it) {
    m.bank_i = it.bank < 4 ? 1u << it.bank : 0u;
    m.addr_i = it.addr;
    m.frac_i = it.frac;
  };
  auto garbage = [&](Vcos_k_rom_patent& m) {
    m.bank_i = 1u << (junk() % 4);
    m.addr_i = junk() % entries;
    m.frac_i = junk() % 4096;
  };
  auto check = [&](Vcos_k_rom_patent& m, const Item& it) {
    const int b = it.bank < 4 ? static_cast<int>(it.bank) : 0;
    const uint32_t w = want(b, static_cast<int>(it.addr));
    image_mismatches += image[b * entries + it.addr] != w;
    if (static_cast<uint32_t>(m.cosk_o) == w) return std::string();
    std::ostringstream s;
    s << "bank " << it.bank << " addr " << it.addr << ": rtl " << m.cosk_o << ", want " << w;
    return s.str();
  };
  auto any = [](Vcos_k_rom_patent&) { return std::string(); };
  Vcos_k_rom_patent dut;
  constexpr int kRom12PatentLatency = static_cast<int>(Vpipeline_patent_specular_pipeline::Rom12Stages);
  dut.clk_i = 0;
  dut.eval();
  // Same latency as the interpolated build (the word is delayed as long as the d t tree).
  CHECK(run_stream(dut, kRom12PatentLatency, items, apply, garbage, check, any, [](long) { return true; }) == 0);
  CHECK(image_mismatches == 0);
  std::mt19937 stall(9);
  std::vector<Item> some(items.begin(), items.begin() + 3000);
  CHECK(run_stream(dut, kRom12PatentLatency, some, apply, garbage, check, any, [&](long) { return stall() % 3 != 0; }) == 0);
}
