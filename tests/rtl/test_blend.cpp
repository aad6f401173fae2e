// SPDX-License-Identifier: Apache-2.0
// The display-exact device's blocks (docs/display_exact.md): specular_blend on its own, at the
// widths of the B2 and B4 builds and in both multiplier styles, and ROM 12's second read.
// The blend is checked against cos_b = (c1 (2^W - w) + c2 w + 2^(W-1)) >> W, the two-product
// form of the golden model's c1 + ((c2 - c1) w + 2^(W-1)) >> W (equal because c1 2^W is a
// multiple of 2^W), computed here in unsigned integers: a second method, not the RTL's offset
// difference. Latencies come from sim/specular_pipeline.sv (rtl/prim/specular_pkg.sv).
#include "Vblend_b2.h"
#include "Vblend_b2_t18.h"
#include "Vblend_b4_t16.h"
#include "Vcos_k_rom_blend_b2.h"
#include "Vpipeline_default_specular_pipeline.h"
#include "Vpipeline_blend_b4_specular_pipeline.h"
#include "pipe_stream.hpp"
#include "rtl_harness.hpp"

#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using specular::rtl_test::run_stream;
using specular::rtl_test::tick;

namespace {

struct BlendItem {
  uint32_t c1, c2, w;
  bool z1, z2;
};

// The expected cos_b: each read zeroed by its flag, then the two-product form.
uint32_t blend_ref(const BlendItem& it, int w_bits) {
  const uint64_t c1 = it.z1 ? 0 : it.c1, c2 = it.z2 ? 0 : it.c2;
  return static_cast<uint32_t>((c1 * ((uint64_t{1} << w_bits) - it.w) + c2 * it.w + (uint64_t{1} << (w_bits - 1))) >>
                               w_bits);
}

// Corner cases (every read at 0, 1, the top, one below it, and the weight at 0, 1, half and
// the top, each zero flag) and random reads of at most 1.0.
std::vector<BlendItem> blend_items(int d_bits, int w_bits, int random, uint32_t seed) {
  const uint32_t one = 1U << d_bits, wmax = (1U << w_bits) - 1;
  std::vector<BlendItem> v;
  const uint32_t cs[] = {0, 1, 2, one / 2, one - 1, one};
  const uint32_t ws[] = {0, 1, 1U << (w_bits - 1), wmax - 1, wmax};
  for (uint32_t c1 : cs)
    for (uint32_t c2 : cs)
      for (uint32_t w : ws)
        for (int z = 0; z < 4; ++z) v.push_back({c1, c2, w, (z & 1) != 0, (z & 2) != 0});
  std::mt19937 rng(seed);
  for (int i = 0; i < random; ++i) {
    BlendItem it{static_cast<uint32_t>(rng() % (one + 1)), static_cast<uint32_t>(rng() % (one + 1)),
                 static_cast<uint32_t>(rng() & wmax), rng() % 16 == 0, rng() % 16 == 0};
    // Neighbouring banks read close values most of the time: half the items differ by a little.
    if (i % 2) it.c2 = std::min(one, it.c1 + static_cast<uint32_t>(rng() % 64));
    v.push_back(it);
  }
  return v;
}

template <class M>
int run_blend(M& dut, int latency, int d_bits, int w_bits, const std::vector<BlendItem>& items, bool stalls) {
  std::mt19937 junk(5), rng(6);
  const uint32_t one = 1U << d_bits;
  auto apply = [](M& m, const BlendItem& it) {
    m.c1_i = it.c1;
    m.c2_i = it.c2;
    m.w_i = it.w;
    m.zero1_i = it.z1;
    m.zero2_i = it.z2;
  };
  auto garbage = [&](M& m) {
    m.c1_i = junk() % (one + 1);
    m.c2_i = junk() % (one + 1);
    m.w_i = junk() & ((1U << w_bits) - 1);
    m.zero1_i = junk() & 1;
    m.zero2_i = junk() & 1;
  };
  auto check = [&](M& m, const BlendItem& it) {
    const uint32_t want = blend_ref(it, w_bits), got = m.cosb_o;
    const uint32_t c1 = it.z1 ? 0 : it.c1, c2 = it.z2 ? 0 : it.c2;
    std::ostringstream o;
    if (got != want)
      o << "c1 " << it.c1 << (it.z1 ? " (zeroed)" : "") << " c2 " << it.c2 << (it.z2 ? " (zeroed)" : "") << " w "
        << it.w << ": rtl " << got << ", expected " << want;
    else if (got < std::min(c1, c2) || got > std::max(c1, c2))
      o << "cos_b " << got << " outside [" << std::min(c1, c2) << ", " << std::max(c1, c2) << "]";
    return o.str();
  };
  auto any = [](M&) { return std::string(); };
  auto en = [&](long) { return !stalls || rng() % 3 != 0; };
  dut.clk_i = 0;
  dut.eval();
  return run_stream(dut, latency, items, apply, garbage, check, any, en);
}

using P2 = Vpipeline_default_specular_pipeline;
using P4 = Vpipeline_blend_b4_specular_pipeline;

}  // namespace

TEST_CASE("blend (B2 widths, LUT tree): corners and random reads, bit-exact, one per clock", "[rtl][blend]") {
  REQUIRE(P2::BlendStages > 0);
  Vblend_b2 dut;
  CHECK(run_blend(dut, P2::BlendStages, 12, 10, blend_items(12, 10, 30000, 1), false) == 0);
}

TEST_CASE("blend holds every stage while en_i is low (stall)", "[rtl][blend][stall]") {
  Vblend_b2 dut;
  CHECK(run_blend(dut, P2::BlendStages, 12, 10, blend_items(12, 10, 10000, 2), true) == 0);
}

TEST_CASE("blend in DSP tiles (ECP5 18, B2 widths; UP5K 16, B4 widths): same values, same latency",
          "[rtl][blend]") {
  Vblend_b2_t18 d18;
  CHECK(run_blend(d18, P2::BlendStages, 12, 10, blend_items(12, 10, 10000, 3), true) == 0);
  Vblend_b4_t16 d16;
  CHECK(run_blend(d16, P4::BlendStages, 14, 9, blend_items(14, 9, 10000, 4), true) == 0);
}

TEST_CASE("ROM 12 with two reads (B2 build): each read is its own bank, entry and weight", "[rtl][rom][blend]") {
  const specular::BuildConfig& bc = specular::build_config("default");
  const specular::device::Format& f = bc.f;
  REQUIRE(f.blend);
  const std::vector<uint32_t> image = specular::read_hex(bc.cos_hex(), f.cos_word_bits(), f.cos_rom_depth());
  const int banks = static_cast<int>(f.banks.size()), entries = 1 << f.cos_addr_bits;
  const uint32_t frac_mask = (1U << f.cos_frac_bits) - 1;
  struct Item {
    unsigned bank[2], addr[2], frac[2];
  };
  // cos^k of one read from the committed words: v - ((d t + 2^(F-1)) >> F).
  auto expect = [&](unsigned bank, unsigned addr, unsigned frac) {
    const uint32_t w = image[bank * entries + addr];
    const uint32_t v = w >> f.cos_delta_bits, d = w & ((1U << f.cos_delta_bits) - 1);
    return v - ((d * frac + (1U << (f.cos_frac_bits - 1))) >> f.cos_frac_bits);
  };
  std::vector<Item> items;
  std::mt19937 rng(21);
  for (int b = 0; b < banks; ++b)
    for (int a = 0; a < entries; ++a)  // every word on both ports, the other port elsewhere
      items.push_back({{static_cast<unsigned>(b), static_cast<unsigned>((b + 1) % banks)},
                       {static_cast<unsigned>(a), static_cast<unsigned>(entries - 1 - a)},
                       {static_cast<unsigned>(rng() & frac_mask), static_cast<unsigned>(rng() & frac_mask)}});
  for (int i = 0; i < 20000; ++i)
    items.push_back({{static_cast<unsigned>(rng() % banks), static_cast<unsigned>(rng() % banks)},
                     {static_cast<unsigned>(rng() % entries), static_cast<unsigned>(rng() % entries)},
                     {static_cast<unsigned>(rng() & frac_mask), static_cast<unsigned>(rng() & frac_mask)}});
  const int field = f.cos_data_bits + 1;
  auto apply = [&](Vcos_k_rom_blend_b2& m, const Item& it) {
    m.bank_i = (1U << it.bank[0]) | ((1U << it.bank[1]) << banks);
    m.addr_i = it.addr[0] | (it.addr[1] << f.cos_addr_bits);
    m.frac_i = it.frac[0] | (it.frac[1] << f.cos_frac_bits);
  };
  std::mt19937 junk(22);
  auto garbage = [&](Vcos_k_rom_blend_b2& m) {
    m.bank_i = (1U << (junk() % banks)) | ((1U << (junk() % banks)) << banks);
    m.addr_i = junk() & ((1U << (2 * f.cos_addr_bits)) - 1);
    m.frac_i = junk() & ((1U << (2 * f.cos_frac_bits)) - 1);
  };
  auto check = [&](Vcos_k_rom_blend_b2& m, const Item& it) {
    std::ostringstream o;
    for (int r = 0; r < 2; ++r) {
      const uint32_t got = (static_cast<uint64_t>(m.cosk_o) >> (r * field)) & ((1U << field) - 1);
      const uint32_t want = expect(it.bank[r], it.addr[r], it.frac[r]);
      if (got != want)
        o << "read " << r << " bank " << it.bank[r] << " addr " << it.addr[r] << " frac " << it.frac[r] << ": rtl "
          << got << ", expected " << want << "; ";
    }
    return o.str();
  };
  auto any = [](Vcos_k_rom_blend_b2&) { return std::string(); };
  Vcos_k_rom_blend_b2 dut;
  dut.clk_i = 0;
  dut.eval();
  std::mt19937 stall(23);
  CHECK(run_stream(dut, P2::Rom12Stages, items, apply, garbage, check, any, [&](long) { return stall() % 4 != 0; }) ==
        0);
}
