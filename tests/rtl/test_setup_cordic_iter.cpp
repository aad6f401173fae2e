// SPDX-License-Identifier: Apache-2.0
// The folded CORDIC (rtl/setup/specular_setup_cordic_iter.sv) against its golden model
// host::lean::cordic_angle(x, y, Frac, Iters, W), bit for bit, in six configurations (each its
// own Verilator model, tests/rtl/CMakeLists.txt): PerClock = 1, 4, 7 and 28 at W 34 / Frac 29 /
// Iters 28 (the lean setup's widths), PerClock = 1 with OpReg (two clocks an iteration, the
// folded lean setup's copies from SetupII 58 on), and PerClock = 5 at W 40 / Frac 33 / Iters 32,
// where PerClock divides no Iters and the last round's stages idle. Each gets 20,000 random vectors of
// every magnitude and quadrant (the axes, the half turn's cases x < 0 with y = 0, tiny vectors,
// vectors near the width limit |(x, y)| K < 2^(W-1-Frac)) under random input gaps, output
// backpressure and resets; the AXI4-Stream rules on the output (valid and data hold until the
// transfer); the initiation interval and latency, measured, equal to the module's II and Latency
// and to ceil(Iters / PerClock) + 1 (2 ceil(Iters / PerClock) + 1 with OpReg); and a reset in the middle of a vector and while its result
// waits.
#include "Vcordic_iter_pc1.h"
#include "Vcordic_iter_pc1_opreg.h"
#include "Vcordic_iter_pc1_opreg_specular_setup_cordic_iter.h"
#include "Vcordic_iter_pc1_specular_setup_cordic_iter.h"
#include "Vcordic_iter_pc28.h"
#include "Vcordic_iter_pc28_specular_setup_cordic_iter.h"
#include "Vcordic_iter_pc4.h"
#include "Vcordic_iter_pc4_specular_setup_cordic_iter.h"
#include "Vcordic_iter_pc7.h"
#include "Vcordic_iter_pc7_specular_setup_cordic_iter.h"
#include "Vcordic_iter_w40_pc5.h"
#include "Vcordic_iter_w40_pc5_specular_setup_cordic_iter.h"
#include "rtl_harness.hpp"
#include "setup_lean.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <deque>
#include <iterator>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using specular::rtl_test::reset;
using specular::rtl_test::tick;
namespace hl = specular::host::lean;

// The configuration of a model (its -G parameters in tests/rtl/CMakeLists.txt).
struct Config {
  int w, frac, iters, per_clock;
  bool op_reg = false;  // two clocks an iteration
  int ii() const { return (op_reg ? 2 : 1) * ((iters + per_clock - 1) / per_clock) + 1; }
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

int64_t golden(const Config& c, const Vec2& v) { return hl::cordic_angle(v.x, v.y, c.frac, c.iters, c.w); }

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
  size_t accepted = 0, checked = 0, mismatches = 0, hold_violations = 0, resets = 0;
  long min_interval = -1;  // the shortest time between two accepts without a reset between
  std::string first_mismatch;
};

// Offers `vecs` in order (each held until accepted), with the given probabilities per cycle of
// offering a new vector, of out_ready_i and of an asynchronous reset; at a reset the vector in
// flight is dropped and the one offered is offered again. Checks every output against the
// golden model in order and the AXI4-Stream hold rule.
template <class M>
Stats run(M& m, const Config& c, const std::vector<Vec2>& vecs, double p_valid, double p_ready, double p_reset,
          uint64_t seed) {
  Stats st;
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution valid_d(p_valid), ready_d(p_ready), reset_d(p_reset);
  reset(m);
  std::deque<int64_t> expected;
  size_t next = 0;
  bool offering = false, held = false;  // held: out_valid_o without out_ready_i last cycle
  uint64_t held_angle = 0;
  long last_accept = -1;
  const long limit = static_cast<long>(vecs.size()) * (c.ii() + 2) * 20 + 1000;
  for (long cycle = 0; (next < vecs.size() || !expected.empty()) && cycle < limit; ++cycle) {
    if (next < vecs.size() && !offering) offering = valid_d(rng);
    m.in_valid_i = offering;
    if (offering) {
      m.x_i = to_port(vecs[next].x, c.w);
      m.y_i = to_port(vecs[next].y, c.w);
    } else {
      m.x_i = rng() & ((uint64_t{1} << c.w) - 1);  // garbage while not offering
      m.y_i = rng();
      m.y_i &= (uint64_t{1} << c.w) - 1;
    }
    // Drain with out_ready_i high once every vector is in.
    m.out_ready_i = next >= vecs.size() || ready_d(rng);
    m.eval();
    if (held && (!m.out_valid_o || m.angle_o != held_angle)) ++st.hold_violations;
    if (m.out_valid_o && m.out_ready_i) {  // each transfer once (the hold rule covers the cycles before)
      if (expected.empty()) {
        ++st.mismatches;
        if (st.first_mismatch.empty()) st.first_mismatch = "an output with none expected";
      } else {
        const int64_t got = sext(m.angle_o, c.w);
        if (got != expected.front()) {
          ++st.mismatches;
          if (st.first_mismatch.empty())
            st.first_mismatch = "vector " + std::to_string(st.checked) + ": RTL " + std::to_string(got) + ", model " +
                                std::to_string(expected.front());
        }
      }
    }
    held = m.out_valid_o && !m.out_ready_i;
    held_angle = m.angle_o;
    if (m.out_valid_o && m.out_ready_i) {
      if (!expected.empty()) expected.pop_front();
      ++st.checked;
    }
    if (offering && m.in_ready_o) {
      expected.push_back(golden(c, vecs[next]));
      ++next;
      ++st.accepted;
      offering = false;
      if (last_accept >= 0 && (st.min_interval < 0 || cycle - last_accept < st.min_interval))
        st.min_interval = cycle - last_accept;
      last_accept = cycle;
    }
    if (reset_d(rng)) {
      // The vector in flight (and the one just accepted) is dropped; what was offered and
      // accepted in this cycle is offered again.
      if (m.in_valid_i && m.in_ready_o && !offering) {
        --next;
        --st.accepted;
        offering = true;
      }
      reset(m);
      expected.clear();
      held = false;
      last_accept = -1;
      ++st.resets;
      continue;
    }
    tick(m);
  }
  return st;
}

// Back to back with out_ready_i high: every accept II clocks after the one before, the result
// Latency clocks after its accept.
template <class M>
void check_rate(M& m, const Config& c, int rtl_ii, int rtl_latency) {
  CHECK(rtl_ii == c.ii());
  CHECK(rtl_latency == c.ii());
  const std::vector<Vec2> vecs = make_vectors(c, 200, 5, nullptr);
  reset(m);
  std::vector<long> accepts, outs;
  size_t next = 0, out = 0;
  for (long cycle = 0; out < vecs.size() && cycle < 100000; ++cycle) {
    m.in_valid_i = next < vecs.size();
    if (next < vecs.size()) {
      m.x_i = to_port(vecs[next].x, c.w);
      m.y_i = to_port(vecs[next].y, c.w);
    }
    m.out_ready_i = 1;
    m.eval();
    if (m.out_valid_o) {
      CHECK(sext(m.angle_o, c.w) == golden(c, vecs[out]));
      outs.push_back(cycle);
      ++out;
    }
    if (m.in_valid_i && m.in_ready_o) {
      accepts.push_back(cycle);
      ++next;
    }
    tick(m);
  }
  REQUIRE(out == vecs.size());
  REQUIRE(accepts.size() == vecs.size());
  size_t bad_ii = 0, bad_latency = 0;
  for (size_t i = 1; i < accepts.size(); ++i) bad_ii += accepts[i] - accepts[i - 1] != c.ii();
  for (size_t i = 0; i < outs.size(); ++i) bad_latency += outs[i] - accepts[i] != rtl_latency;
  WARN("W " << c.w << ", Frac " << c.frac << ", Iters " << c.iters << ", PerClock " << c.per_clock
            << ": measured II " << (accepts[1] - accepts[0]) << " clocks, latency " << (outs[0] - accepts[0])
            << " (documented " << rtl_ii << ", " << rtl_latency << ")");
  CHECK(bad_ii == 0);
  CHECK(bad_latency == 0);
}

// A reset in the middle of a vector's rounds, and one while its result waits: the vector is
// dropped (out_valid_o falls at once, in_ready_o rises), the next comes out right.
template <class M>
void check_reset(M& m, const Config& c) {
  const Vec2 a{-(int64_t{1} << c.frac), 12345}, b{int64_t{3} << (c.frac - 2), -(int64_t{5} << (c.frac - 3))};
  for (int wait : {c.ii() / 2, c.ii() + 3}) {
    reset(m);
    m.in_valid_i = 1;
    m.x_i = to_port(a.x, c.w);
    m.y_i = to_port(a.y, c.w);
    m.out_ready_i = 0;
    m.eval();
    REQUIRE(m.in_ready_o);
    tick(m);
    m.in_valid_i = 0;
    for (int i = 0; i < wait; ++i) {
      m.eval();
      CHECK_FALSE(m.in_ready_o);  // busy, or its result waits for out_ready_i
      tick(m);
    }
    m.eval();
    CHECK(m.out_valid_o == (wait >= c.ii() - 1));
    m.rst_ni = 0;  // asynchronous: without a clock edge
    m.eval();
    CHECK_FALSE(m.out_valid_o);
    CHECK(m.in_ready_o);
    tick(m);
    m.rst_ni = 1;
    m.eval();
    CHECK_FALSE(m.out_valid_o);
    // The next vector, alone.
    m.in_valid_i = 1;
    m.x_i = to_port(b.x, c.w);
    m.y_i = to_port(b.y, c.w);
    m.out_ready_i = 1;
    m.eval();
    REQUIRE(m.in_ready_o);
    tick(m);
    m.in_valid_i = 0;
    int outs = 0;
    for (int i = 0; i < 3 * c.ii(); ++i) {
      m.eval();
      if (m.out_valid_o) {
        ++outs;
        CHECK(sext(m.angle_o, c.w) == golden(c, b));
      }
      tick(m);
    }
    CHECK(outs == 1);
  }
}

template <class M>
void check_random(M& m, const Config& c) {
  size_t rejected = 0;
  const std::vector<Vec2> vecs = make_vectors(c, 20000, 1234 + c.per_clock, &rejected);
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
  WARN(c.w << "/" << c.frac << "/" << c.iters << "/" << c.per_clock << ": " << vecs.size() << " vectors; quadrants " << quadrant[0] << " " << quadrant[1] << " " << quadrant[2] << " " << quadrant[3] << ", x < 0 y = 0 "
                    << neg_x_zero_y << ", x > 0 y = 0 " << pos_x_zero_y << ", tiny " << tiny << ", near the limit "
                    << near_limit << ", rejected by the model " << rejected);
  for (size_t q : quadrant) CHECK(q > 1000);
  CHECK(neg_x_zero_y > 100);
  CHECK(pos_x_zero_y > 100);
  CHECK(tiny > 1000);
  CHECK(near_limit > 1000);
  CHECK(vecs.size() >= 20000);
  struct Mode {
    double p_valid, p_ready, p_reset;
  };
  const Mode mode = GENERATE(Mode{1.0, 1.0, 0.0}, Mode{0.6, 0.5, 0.0}, Mode{0.9, 0.7, 0.0003});
  const Stats st = run(m, c, vecs, mode.p_valid, mode.p_ready, mode.p_reset, 99 + c.per_clock);
  INFO(st.first_mismatch);
  WARN("W " << c.w << ", Frac " << c.frac << ", Iters " << c.iters << ", PerClock " << c.per_clock << ", valid "
            << mode.p_valid << ", ready " << mode.p_ready << ", reset " << mode.p_reset << ": " << st.checked
            << " angles checked bit for bit, " << st.mismatches << " mismatches, " << st.resets << " resets");
  CHECK(st.accepted == vecs.size());
  CHECK(st.mismatches == 0);
  CHECK(st.hold_violations == 0);
  CHECK(st.min_interval >= c.ii());
  if (mode.p_reset == 0.0) CHECK(st.checked == vecs.size());
  else CHECK(st.resets > 0);
}

// The configurations of the models (tests/rtl/CMakeLists.txt).
constexpr Config kPc1{34, 29, 28, 1}, kPc1OpReg{34, 29, 28, 1, true}, kPc4{34, 29, 28, 4}, kPc7{34, 29, 28, 7},
    kPc28{34, 29, 28, 28}, kW40Pc5{40, 33, 32, 5};

}  // namespace

#define CORDIC_ITER_TESTS(Model, cfg, name)                                                                    \
  TEST_CASE(name ": 20,000 random vectors bit-exact under gaps, backpressure and resets", "[cordic_iter]") { \
    Model m;                                                                                                   \
    check_random(m, cfg);                                                                                      \
  }                                                                                                            \
  TEST_CASE(name ": initiation interval and latency as documented", "[cordic_iter]") {                       \
    Model m;                                                                                                   \
    check_rate(m, cfg, Model##_specular_setup_cordic_iter::II, Model##_specular_setup_cordic_iter::Latency);   \
  }                                                                                                            \
  TEST_CASE(name ": a reset in the middle of a vector", "[cordic_iter]") {                                   \
    Model m;                                                                                                   \
    check_reset(m, cfg);                                                                                       \
  }

CORDIC_ITER_TESTS(Vcordic_iter_pc1, kPc1, "W 34 Frac 29 Iters 28 PerClock 1")
CORDIC_ITER_TESTS(Vcordic_iter_pc1_opreg, kPc1OpReg, "W 34 Frac 29 Iters 28 PerClock 1 OpReg")
CORDIC_ITER_TESTS(Vcordic_iter_pc4, kPc4, "W 34 Frac 29 Iters 28 PerClock 4")
CORDIC_ITER_TESTS(Vcordic_iter_pc7, kPc7, "W 34 Frac 29 Iters 28 PerClock 7")
CORDIC_ITER_TESTS(Vcordic_iter_pc28, kPc28, "W 34 Frac 29 Iters 28 PerClock 28")
CORDIC_ITER_TESTS(Vcordic_iter_w40_pc5, kW40Pc5, "W 40 Frac 33 Iters 32 PerClock 5")
