// SPDX-License-Identifier: Apache-2.0
// The folded setup's tile multiplier unit (rtl/setup/specular_setup_fmul.sv) against exact
// 128-bit products, in seven configurations (each its own Verilator model,
// tests/rtl/CMakeLists.txt) chosen for the unit's cases: one chunk per product and two (summed
// at the end), a chunk that ends inside a diagonal and one that starts inside one, a zero tile
// (an odd split: 3 x 3 tiles in two chunks of 5), a one-tile product, several chunks per
// multiplier with a last multiplier not full, and both tile selects (a decode of the slot count
// for at most 12 steps, a one-hot token above). Each slot holds random operands (every width's
// extremes among them) for SetupII clocks or, at random, longer (a stalled stage); after the
// advance every p_o lane must be a_j * b_j, and pc_o must hold the same in the advancing clock
// (with Stages = 0, two of the configurations, p_o is read there too: it is pc_o).
// The full-rate product specular_setup_smul (SetupII = 1) the same way in six configurations:
// one tile, 2 x 2, 2 x 3 and 3 x 4 signed tiles (one to four adder levels), the 16-bit tiles of
// the UP5K and the LUT tree of magnitudes; every enabled clock takes a new pair, a random third
// of the clocks stall, and p_o must be the product of the pair taken smul_stages enabled
// clocks earlier.
#include "Vsetup_fmul_a18b18_ii5.h"
#include "Vsetup_fmul_a18b69_ii16.h"
#include "Vsetup_fmul_a20b20_ii6.h"
#include "Vsetup_fmul_a35b35_ii32.h"
#include "Vsetup_fmul_a35b35_ii8.h"
#include "Vsetup_fmul_a35b52_ii8.h"
#include "Vsetup_fmul_a52b52_ii8.h"
#include "Vsetup_smul_a18b18_t18.h"
#include "Vsetup_smul_a20b20_t16.h"
#include "Vsetup_smul_a28b28_t0.h"
#include "Vsetup_smul_a28b28_t18.h"
#include "Vsetup_smul_a35b52_t18.h"
#include "Vsetup_smul_a36b53_t18.h"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace {

using specular::rtl_test::tick;
__extension__ using i128 = __int128;
__extension__ using u128 = unsigned __int128;

// A model's parameters (its -G values in tests/rtl/CMakeLists.txt).
struct Config {
  int n, a_bits, b_bits, setup_ii;
  int stages = 1;  // specular_setup_fmul's Stages: 0, p_o is pc_o (read in the advancing clock)
};

// A port of any width as 32-bit words: Verilator's CData .. QData, or VlWide for more than 64 bits.
template <class Port>
void put_words(Port& port, const std::vector<uint32_t>& w) {
  if constexpr (std::is_integral_v<Port>) {
    uint64_t v = w[0];
    if (w.size() > 1) v |= static_cast<uint64_t>(w[1]) << 32;
    port = static_cast<Port>(v);
  } else {
    for (size_t i = 0; i < w.size(); ++i) port[i] = w[i];
  }
}
template <class Port>
std::vector<uint32_t> get_words(const Port& port, size_t words) {
  std::vector<uint32_t> w(words, 0);
  if constexpr (std::is_integral_v<Port>) {
    const auto v = static_cast<uint64_t>(port);
    w[0] = static_cast<uint32_t>(v);
    if (words > 1) w[1] = static_cast<uint32_t>(v >> 32);
  } else {
    for (size_t i = 0; i < words; ++i) w[i] = port[i];
  }
  return w;
}

// Bits lsb .. lsb + width - 1 of a word vector (width <= 127), as a two's complement field.
void set_field(std::vector<uint32_t>& w, int lsb, int width, i128 v) {
  const auto u = static_cast<u128>(v);
  for (int b = 0; b < width; ++b) {
    const uint32_t bit = static_cast<uint32_t>((u >> b) & 1u);
    const int p = lsb + b;
    w[static_cast<size_t>(p / 32)] = (w[static_cast<size_t>(p / 32)] & ~(1u << (p % 32))) | (bit << (p % 32));
  }
}
i128 get_field(const std::vector<uint32_t>& w, int lsb, int width) {
  u128 u = 0;
  for (int b = 0; b < width; ++b) {
    const int p = lsb + b;
    u |= static_cast<u128>((w[static_cast<size_t>(p / 32)] >> (p % 32)) & 1u) << b;
  }
  const u128 sign = static_cast<u128>(1) << (width - 1);
  return static_cast<i128>((u ^ sign) - sign);
}

// A random signed w-bit operand: the extremes, small values, powers of two, or any bit pattern.
i128 operand(std::mt19937_64& rng, int w) {
  const i128 lo = -(static_cast<i128>(1) << (w - 1));
  const i128 hi = (static_cast<i128>(1) << (w - 1)) - 1;
  switch (rng() % 8) {
    case 0: {
      const i128 edge[] = {lo, hi, 0, 1, -1, lo + 1, hi - 1};
      return edge[rng() % std::size(edge)];
    }
    case 1: {
      const i128 p = static_cast<i128>(1) << (rng() % static_cast<uint64_t>(w - 1));
      return (rng() & 1) ? p : -p;
    }
    case 2: return static_cast<i128>(rng() % 512) - 256;
    default: {
      const u128 u = (static_cast<u128>(rng()) << 64) | rng();
      const u128 sign = static_cast<u128>(1) << (w - 1);
      const u128 masked = u & ((sign << 1) - 1);
      return static_cast<i128>((masked ^ sign) - sign);
    }
  }
}

size_t words_of(int bits) { return static_cast<size_t>((bits + 31) / 32); }

template <class Model>
void check_unit(const Config& c, uint64_t seed, int slots) {
  Model m;
  const int p_bits = c.a_bits + c.b_bits;
  std::mt19937_64 rng(seed);
  std::vector<uint32_t> a(words_of(c.n * c.a_bits)), b(words_of(c.n * c.b_bits));
  std::vector<i128> av(static_cast<size_t>(c.n)), bv(static_cast<size_t>(c.n));
  auto load = [&] {
    for (int j = 0; j < c.n; ++j) {
      av[static_cast<size_t>(j)] = operand(rng, c.a_bits);
      bv[static_cast<size_t>(j)] = operand(rng, c.b_bits);
      set_field(a, j * c.a_bits, c.a_bits, av[static_cast<size_t>(j)]);
      set_field(b, j * c.b_bits, c.b_bits, bv[static_cast<size_t>(j)]);
    }
    put_words(m.a_i, a);
    put_words(m.b_i, b);
  };
  // The counter aligns at the first advance: one slot first, its result unchecked.
  m.clk_i = 0;
  m.en_i = 0;
  load();
  for (int k = 0; k < c.setup_ii - 1; ++k) tick(m);
  m.en_i = 1;
  tick(m);
  int stalled = 0;
  for (int s = 0; s < slots; ++s) {
    load();
    m.en_i = 0;
    const int extra = (rng() % 4 == 0) ? static_cast<int>(rng() % 6) + 1 : 0;
    stalled += extra > 0;
    for (int k = 0; k < c.setup_ii - 1 + extra; ++k) tick(m);
    m.en_i = 1;
    m.eval();
    const auto pc = get_words(m.pc_o, words_of(c.n * p_bits));
    const auto p_now = get_words(m.p_o, words_of(c.n * p_bits));
    tick(m);
    const auto p = (c.stages == 0) ? p_now : get_words(m.p_o, words_of(c.n * p_bits));
    for (int j = 0; j < c.n; ++j) {
      const i128 want = av[static_cast<size_t>(j)] * bv[static_cast<size_t>(j)];
      const i128 got = get_field(p, j * p_bits, p_bits);
      const i128 got_c = get_field(pc, j * p_bits, p_bits);
      if (got != want || got_c != want) {
        FAIL("slot " << s << " lane " << j << ": a = " << static_cast<double>(av[static_cast<size_t>(j)])
                     << ", b = " << static_cast<double>(bv[static_cast<size_t>(j)]) << ", p_o "
                     << (got == want ? "right" : "wrong") << ", pc_o " << (got_c == want ? "right" : "wrong"));
      }
    }
  }
  CHECK(stalled > slots / 8);  // the stalled slots really occurred
}

// specular_setup_smul's latency, as docs/setup_hw.md#the-rtl states it: three stages
// around specular_pipe_mul's 1 + clog2(ceil(b / 2)).
int smul_latency(int b_bits) {
  int levels = 0;
  while ((1 << levels) < (b_bits + 1) / 2) ++levels;
  return 3 + 1 + levels;
}

template <class Model>
void check_smul(int a_bits, int b_bits, uint64_t seed, int clocks) {
  Model m;
  const int p_bits = a_bits + b_bits;
  const int latency = smul_latency(b_bits);
  std::mt19937_64 rng(seed);
  std::vector<uint32_t> a(words_of(a_bits)), b(words_of(b_bits));
  std::deque<i128> taken;  // the products of the pairs taken, oldest first
  m.clk_i = 0;
  m.en_i = 0;
  int checked = 0, stalls = 0;
  i128 last = 0;
  bool have_last = false;
  for (int k = 0; k < clocks; ++k) {
    const i128 av = operand(rng, a_bits), bv = operand(rng, b_bits);
    set_field(a, 0, a_bits, av);
    set_field(b, 0, b_bits, bv);
    put_words(m.a_i, a);
    put_words(m.b_i, b);
    m.en_i = (rng() % 3 != 0) ? 1 : 0;
    tick(m);
    const i128 got = get_field(get_words(m.p_o, words_of(p_bits)), 0, p_bits);
    if (m.en_i) {
      taken.push_back(av * bv);
      if (static_cast<int>(taken.size()) == latency) {
        if (got != taken.front()) {
          FAIL("clock " << k << ": p_o " << static_cast<double>(got) << ", want "
                        << static_cast<double>(taken.front()));
        }
        taken.pop_front();
        ++checked;
        last = got;
        have_last = true;
      }
    } else {
      ++stalls;
      if (have_last && got != last) FAIL("clock " << k << ": p_o moved in a stall");
    }
  }
  CHECK(checked > clocks / 2);
  CHECK(stalls > clocks / 4);
}

}  // namespace

TEST_CASE("setup smul RTL: the product of the pair taken smul_stages enabled clocks earlier, exact") {
  constexpr int kClocks = 20000;
  SECTION("18 x 18, one signed tile") { check_smul<Vsetup_smul_a18b18_t18>(18, 18, 11, kClocks); }
  SECTION("28 x 28, 2 x 2 tiles") { check_smul<Vsetup_smul_a28b28_t18>(28, 28, 12, kClocks); }
  SECTION("35 x 52, 2 x 3 tiles") { check_smul<Vsetup_smul_a35b52_t18>(35, 52, 13, kClocks); }
  SECTION("36 x 53, 3 x 4 tiles") { check_smul<Vsetup_smul_a36b53_t18>(36, 53, 14, kClocks); }
  SECTION("20 x 20, 16-bit tiles") { check_smul<Vsetup_smul_a20b20_t16>(20, 20, 15, kClocks); }
  SECTION("28 x 28, the LUT tree") { check_smul<Vsetup_smul_a28b28_t0>(28, 28, 16, kClocks); }
}

TEST_CASE("setup fmul RTL: every lane's product exact, each slot held SetupII clocks or stalled longer") {
  constexpr int kSlots = 3000;
  SECTION("35 x 35, SetupII 8: one chunk a product, one product a multiplier") {
    check_unit<Vsetup_fmul_a35b35_ii8>({5, 35, 35, 8}, 1, kSlots);
  }
  SECTION("35 x 52, SetupII 8: two chunks, the second starting inside a diagonal") {
    check_unit<Vsetup_fmul_a35b52_ii8>({3, 35, 52, 8}, 2, kSlots);
  }
  SECTION("52 x 52, SetupII 8: two chunks of 5 of 9 tiles, one zero tile") {
    check_unit<Vsetup_fmul_a52b52_ii8>({2, 52, 52, 8}, 3, kSlots);
  }
  SECTION("18 x 69, SetupII 16: three chunks a multiplier, the last multiplier with one, no p_o register") {
    check_unit<Vsetup_fmul_a18b69_ii16>({7, 18, 69, 16, 0}, 4, kSlots);
  }
  SECTION("35 x 35, SetupII 32: seven chunks a multiplier, the token select, no p_o register") {
    check_unit<Vsetup_fmul_a35b35_ii32>({12, 35, 35, 32, 0}, 5, kSlots);
  }
  SECTION("20 x 20, SetupII 6: two chunks of two tiles") {
    check_unit<Vsetup_fmul_a20b20_ii6>({3, 20, 20, 6}, 6, kSlots);
  }
  SECTION("18 x 18, SetupII 5: one tile a product, two products a multiplier") {
    check_unit<Vsetup_fmul_a18b18_ii5>({4, 18, 18, 5}, 7, kSlots);
  }
}
