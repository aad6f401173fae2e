// SPDX-License-Identifier: Apache-2.0
// The folded CORDIC (rtl/setup/specular_setup_cordic_fold.sv) against its golden model
// host::fixed::cordic_angle(x, y, Frac, Iters, W), bit for bit, in six configurations (each its
// own Verilator model, tests/rtl/CMakeLists.txt): Rounds 2, 3, 7, 15 and 28 at W 34 / Frac 29 /
// Iters 28, the folded setup's at SetupII 6, 8, 16, 32 and 64 (specular_setup_pkg::
// cordic_rounds; 3 and 15 divide no Iters, so the last segment idles), and Rounds 5 at W 40 /
// Frac 33 / Iters 32. Each gets 20,000 random vectors of every magnitude and quadrant (the axes,
// the half turn's cases x < 0 with y = 0, tiny vectors, vectors near the width limit
// |(x, y)| K < 2^(W-1-Frac)) with random gaps between the starts, garbage on the inputs between
// them, and resets; done_o rises exactly Latency clocks after a start (two a round, and one)
// and holds, with angle_o, until the next; the vector of start j leaves after start j + Segs - 1; after a
// reset in the middle of the rounds, every vector started after it comes out right.
#include "Vcordic_fold_r15.h"
#include "Vcordic_fold_r15_specular_setup_cordic_fold.h"
#include "Vcordic_fold_r2.h"
#include "Vcordic_fold_r2_specular_setup_cordic_fold.h"
#include "Vcordic_fold_r28.h"
#include "Vcordic_fold_r28_specular_setup_cordic_fold.h"
#include "Vcordic_fold_r3.h"
#include "Vcordic_fold_r3_specular_setup_cordic_fold.h"
#include "Vcordic_fold_r7.h"
#include "Vcordic_fold_r7_specular_setup_cordic_fold.h"
#include "Vcordic_fold_w40_r5.h"
#include "Vcordic_fold_w40_r5_specular_setup_cordic_fold.h"
#include "rtl_harness.hpp"
#include "setup_fixed.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <iterator>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using specular::rtl_test::reset;
using specular::rtl_test::tick;
namespace hf = specular::host::fixed;

// The configuration of a model (its -G parameters in tests/rtl/CMakeLists.txt).
struct Config {
  int w, frac, iters, rounds;
  int segs() const { return (iters + rounds - 1) / rounds; }
  int latency() const { return 2 * rounds + 1; }
};

struct Vec2 {
  int64_t x, y;
};

int64_t sext(uint64_t v, int w) {
  const uint64_t m = uint64_t{1} << (w - 1);
  v &= (w == 64) ? ~uint64_t{0} : (uint64_t{1} << w) - 1;
  return static_cast<int64_t>((v ^ m) - m);
}
uint64_t to_port(int64_t v, int w) { return static_cast<uint64_t>(v) & ((uint64_t{1} << w) - 1); }

int64_t golden(const Config& c, const Vec2& v) { return hf::cordic_angle(v.x, v.y, c.frac, c.iters, c.w); }

// The vectors: the special cases, then random ones of every kind, each kept only when the
// golden model keeps its registers inside W bits (it throws otherwise); `rejected` counts those.
std::vector<Vec2> make_vectors(const Config& c, size_t n_random, uint64_t seed, size_t* rejected) {
  const long double k_gain = 1.6467602581210656483L;  // prod sqrt(1 + 2^-2i)
  // |(x, y)| K < 2^(W-1): the largest length in LSBs, with a margin for the truncating shifts.
  const long double r_max = (std::ldexp(1.0L, c.w - 1) - 4.0L * c.iters) / k_gain;
  std::vector<Vec2> v;
  size_t rej = 0;
  auto add = [&](int64_t x, int64_t y) {
    try {
      (void)golden(c, {x, y});
      v.push_back({x, y});
    } catch (const std::logic_error&) {
      ++rej;
    }
  };
  const auto big = static_cast<int64_t>(r_max);
  const int64_t specials[] = {0, 1, -1, 2, -2, 3, 7, -7, 1000, -1000, int64_t{1} << c.frac,
                              -(int64_t{1} << c.frac), big / 3, -big / 3, big - 1, -(big - 1)};
  for (int64_t a : specials) {
    add(a, 0);  // y = 0 (x < 0: the half turn with y = 0, angle +pi)
    add(0, a);  // the y axis
    add(a, a), add(a, -a);
    add(a, 1), add(a, -1);  // next to the x axis on both sides
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<long double> ang(-std::numbers::pi_v<long double>, std::numbers::pi_v<long double>);
  std::uniform_real_distribution<long double> unit(0.0L, 1.0L);
  const long double log2_max = std::log2(r_max);
  while (v.size() < n_random + std::size(specials) * 6) {
    const int kind = static_cast<int>(rng() % 8);
    const long double t = ang(rng);
    long double r = 0;
    switch (kind) {
      case 0:  // tiny: integer components in -8..8
        add(static_cast<int64_t>(rng() % 17) - 8, static_cast<int64_t>(rng() % 17) - 8);
        continue;
      case 1:  // near the width limit
        r = r_max * (1.0L - std::ldexp(unit(rng), -static_cast<int>(rng() % 24)));
        break;
      case 2:  // on an axis, any magnitude, either sign
      {
        const auto m = static_cast<int64_t>(std::exp2(unit(rng) * log2_max));
        const int64_t s = (rng() & 1) ? m : -m;
        if (rng() & 1) add(s, 0);
        else add(0, s);
        continue;
      }
      case 3:  // raw integers in the square of side r_max / sqrt 2 (every bit pattern's quadrant)
      {
        const auto h = static_cast<uint64_t>(r_max / std::numbers::sqrt2_v<long double>);
        add(static_cast<int64_t>(rng() % (2 * h + 1)) - static_cast<int64_t>(h),
            static_cast<int64_t>(rng() % (2 * h + 1)) - static_cast<int64_t>(h));
        continue;
      }
      default:  // log-uniform magnitude from 1 LSB to the limit, uniform angle
        r = std::exp2(unit(rng) * log2_max);
        break;
    }
    add(std::llround(r * std::cos(t)), std::llround(r * std::sin(t)));
  }
  if (rejected) *rejected = rej;
  return v;
}

struct Stats {
  size_t started = 0, checked = 0, mismatches = 0, timing_errors = 0, hold_violations = 0, resets = 0;
  std::string first_mismatch;
};

// Starts the vectors one by one, each start `gap` clocks (random, at least Latency) after the
// one before, with garbage on x_i, y_i in between and, with probability p_reset per start, an
// asynchronous reset somewhere in the rounds. Checks done_o's timing, the hold of done_o and
// angle_o until the next start, and every angle of a vector started since the last reset.
template <class M>
Stats run(M& m, const Config& c, const std::vector<Vec2>& vecs, int max_extra_gap, double p_reset, uint64_t seed) {
  Stats st;
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution reset_d(p_reset);
  reset(m);
  // What each segment holds: the golden angle of its vector, or nothing (garbage: loaded before
  // a reset, or never loaded).
  std::deque<std::optional<int64_t>> chain(static_cast<size_t>(c.segs()));
  const uint64_t mask = (uint64_t{1} << c.w) - 1;
  size_t next = 0;
  int t = 0, gap = 0, reset_at = -1;  // t: clocks since the last start (this clock's number)
  bool started = false, checked_this = false, reset_since = false;
  uint64_t held = 0;
  for (;;) {
    const bool start = !started || t >= gap;
    const bool real = start && next < vecs.size();
    m.start_i = start;
    m.x_i = real ? to_port(vecs[next].x, c.w) : (rng() & mask);  // garbage between the starts
    m.y_i = real ? to_port(vecs[next].y, c.w) : (rng() & mask);
    if (t == reset_at) {
      m.rst_ni = 0;  // asynchronous
      m.eval();
      m.rst_ni = 1;
      for (auto& e : chain) e.reset();
      reset_since = true;
      ++st.resets;
    }
    m.eval();
    if (started) {
      const bool want_done = !reset_since && t >= c.latency();
      if (static_cast<bool>(m.done_o) != want_done) ++st.timing_errors;
      if (want_done && chain.back().has_value()) {
        if (!checked_this) {
          ++st.checked;
          checked_this = true;
          held = m.angle_o;
          const int64_t got = sext(m.angle_o, c.w);
          if (got != *chain.back()) {
            ++st.mismatches;
            if (st.first_mismatch.empty())
              st.first_mismatch = "angle " + std::to_string(st.checked) + ": RTL " + std::to_string(got) + ", model " +
                                  std::to_string(*chain.back());
          }
        } else if (m.angle_o != held) {
          ++st.hold_violations;
        }
      }
    }
    tick(m);
    ++t;
    if (!start) continue;
    chain.pop_back();
    chain.push_front(real ? std::optional<int64_t>(golden(c, vecs[next])) : std::nullopt);
    if (real) ++next, ++st.started;
    if (next >= vecs.size() && std::none_of(chain.begin(), chain.end(), [](const auto& e) { return e.has_value(); }))
      break;
    started = true;
    t = 1;
    gap = c.latency() + static_cast<int>(rng() % static_cast<uint64_t>(max_extra_gap + 1));
    reset_at = reset_d(rng) ? 1 + static_cast<int>(rng() % static_cast<uint64_t>(c.latency() - 1)) : -1;
    checked_this = reset_since = false;
  }
  return st;
}

template <class M>
void check_random(M& m, const Config& c, int rtl_segs, int rtl_latency) {
  CHECK(rtl_segs == c.segs());
  CHECK(rtl_latency == c.latency());
  size_t rejected = 0;
  const std::vector<Vec2> vecs = make_vectors(c, 20000, 1234 + c.rounds, &rejected);
  // Every quadrant and both axis cases the half turn treats apart appear.
  size_t quadrant[4] = {}, neg_x_zero_y = 0, pos_x_zero_y = 0, tiny = 0, near_limit = 0;
  const long double lim = std::ldexp(1.0L, c.w - 1 - c.frac) / 1.6467602581210656483L * std::ldexp(1.0L, c.frac);
  for (const Vec2& v : vecs) {
    quadrant[(v.x < 0 ? 1 : 0) + (v.y < 0 ? 2 : 0)]++;
    neg_x_zero_y += v.x < 0 && v.y == 0;
    pos_x_zero_y += v.x > 0 && v.y == 0;
    tiny += std::abs(v.x) < 16 && std::abs(v.y) < 16;
    near_limit += std::hypot(static_cast<long double>(v.x), static_cast<long double>(v.y)) > 0.99L * lim;
  }
  for (size_t q : quadrant) CHECK(q > 1000);
  CHECK(neg_x_zero_y > 100);
  CHECK(pos_x_zero_y > 100);
  CHECK(tiny > 1000);
  CHECK(near_limit > 1000);
  CHECK(vecs.size() >= 20000);
  struct Mode {
    int max_extra_gap;
    double p_reset;
  };
  const Mode mode = GENERATE(Mode{0, 0.0}, Mode{5, 0.0}, Mode{2, 0.002});
  const Stats st = run(m, c, vecs, mode.max_extra_gap, mode.p_reset, 99 + c.rounds);
  INFO(st.first_mismatch);
  WARN("W " << c.w << ", Frac " << c.frac << ", Iters " << c.iters << ", Rounds " << c.rounds << " (" << c.segs()
            << " segments), extra gap up to " << mode.max_extra_gap << ", reset " << mode.p_reset << ": " << st.checked
            << " angles checked bit for bit, " << st.mismatches << " mismatches, " << st.resets << " resets; "
            << rejected << " vectors rejected by the model");
  CHECK(st.started == vecs.size());
  CHECK(st.mismatches == 0);
  CHECK(st.timing_errors == 0);
  CHECK(st.hold_violations == 0);
  if (mode.p_reset == 0.0) {
    CHECK(st.checked == vecs.size());
  } else {
    CHECK(st.resets > 0);
    CHECK(st.checked + st.resets * static_cast<size_t>(c.segs()) >= vecs.size());
  }
}

// The configurations of the models (tests/rtl/CMakeLists.txt).
constexpr Config kR2{34, 29, 28, 2}, kR3{34, 29, 28, 3}, kR7{34, 29, 28, 7}, kR15{34, 29, 28, 15},
    kR28{34, 29, 28, 28}, kW40R5{40, 33, 32, 5};

}  // namespace

#define CORDIC_FOLD_TESTS(Model, cfg, name)                                                                        \
  TEST_CASE(name ": 20,000 random vectors bit-exact with gaps and resets, done_o on time", "[cordic_fold]") {  \
    Model m;                                                                                                       \
    check_random(m, cfg, Model##_specular_setup_cordic_fold::Segs, Model##_specular_setup_cordic_fold::Latency); \
  }

CORDIC_FOLD_TESTS(Vcordic_fold_r2, kR2, "W 34 Frac 29 Iters 28 Rounds 2")
CORDIC_FOLD_TESTS(Vcordic_fold_r3, kR3, "W 34 Frac 29 Iters 28 Rounds 3")
CORDIC_FOLD_TESTS(Vcordic_fold_r7, kR7, "W 34 Frac 29 Iters 28 Rounds 7")
CORDIC_FOLD_TESTS(Vcordic_fold_r15, kR15, "W 34 Frac 29 Iters 28 Rounds 15")
CORDIC_FOLD_TESTS(Vcordic_fold_r28, kR28, "W 34 Frac 29 Iters 28 Rounds 28")
CORDIC_FOLD_TESTS(Vcordic_fold_w40_r5, kW40R5, "W 40 Frac 33 Iters 32 Rounds 5")
