// SPDX-License-Identifier: Apache-2.0
//
// The RGB core: specular_stream with Channels = 3 (rtl/core/specular_stream.sv,
// docs/interfaces.md#stream-interface-specular_stream). A span carries three values of C
// (span_c_i, channel 0 in the low CBits) and every pixel three intensities (px_intensity_o
// likewise), one multiplier 13 per channel on the pixel's one cos^k. Verilated at the default
// build, the blend (Vstream_rgb), and at the single-bank build (Vstream_rgb_single, the -G flags
// of roms/build_configs.cmake), each checked:
//   - against the golden model's per-channel function (DeviceModel::rgb_pixel), every pixel of
//     every channel bit-exactly, with its tag and last flag, under random span gaps, random
//     px_ready_i backpressure, garbage on the span bus while span_valid_i is low and a reset
//     in the middle of the stream (the pixels before it a prefix of the expected ones, none
//     after it before a new span, the spans after it exact);
//   - channel by channel against the scalar model (DeviceModel::pixel with C = C_ch, what the
//     Channels = 1 core outputs for that span): the second, independent expectation;
//   - the pixel handshake rules: valid held and the pixel unchanged while stalled, 0 while
//     invalid;
//   - throughput and latency: back-to-back spans of 1 to 4 pixels offered every clock with
//     px_ready_i high give one pixel per clock from the first pixel to the last, and the first
//     pixel StreamLatency clocks after its accept (sim/specular_pipeline.sv, from
//     rtl/prim/specular_pkg.sv: the scalar build's latency).
// specular_axis at Channels = 3 (Vaxis_rgb) runs in lock step with Vstream_rgb: its
// descriptor is {len, n, dpsi, psi0, c} with c 3 * CBits wide.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter headers
#include "Vaxis_rgb.h"
#include "Vaxis_rgb_specular_axis.h"
#include "Vpipeline_rgb_default_specular_pipeline.h"
#include "Vpipeline_rgb_single_specular_pipeline.h"
#include "Vstream_rgb.h"
#include "Vstream_rgb_single.h"
#include "Vstream_rgb_single_specular_stream.h"
#include "Vstream_rgb_specular_stream.h"
#pragma GCC diagnostic pop

#include "device_model.hpp"
#include "rom_image.hpp"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace specular::rtl_test;
namespace dev = specular::device;

namespace {

constexpr int kChannels = 3;

struct RgbSpan {
  dev::Registers reg;  // reg.c unused: the colour is `c`
  dev::RgbC c{};
  uint32_t tag = 0;
};

struct Px {
  uint64_t data = 0;  // Channels * CBits: channel ch in bits [ch * CBits, (ch + 1) * CBits)
  bool last = false;
  uint32_t tag = 0;
  bool operator==(const Px&) const = default;
};

uint64_t pack_c(const dev::RgbC& c, int c_bits) {
  uint64_t v = 0;
  for (int ch = 0; ch < kChannels; ++ch) v |= static_cast<uint64_t>(c[static_cast<size_t>(ch)]) << (ch * c_bits);
  return v;
}

uint32_t channel(uint64_t data, int ch, int c_bits) {
  return static_cast<uint32_t>((data >> (ch * c_bits)) & ((uint64_t{1} << c_bits) - 1));
}

// The expected pixels of a span sequence, two ways: the per-channel model (rgb_pixel) and the
// scalar model once per channel (pixel() with C = C_ch), packed as the RTL packs them.
struct Expected {
  std::vector<Px> rgb, scalar;
};
Expected expect(const dev::DeviceModel& model, const std::vector<RgbSpan>& spans) {
  const int cb = model.format().c_bits;
  Expected e;
  for (const RgbSpan& s : spans) {
    for (uint32_t i = 0; i <= s.reg.len; ++i) {
      const bool last = i == s.reg.len;
      e.rgb.push_back({pack_c(model.rgb_pixel(s.reg, s.c, static_cast<int>(i)), cb), last, s.tag});
      dev::RgbC sc{};
      for (size_t ch = 0; ch < sc.size(); ++ch) {
        dev::Registers r = s.reg;
        r.c = s.c[ch];
        sc[ch] = model.pixel(r, static_cast<int>(i));
      }
      e.scalar.push_back({pack_c(sc, cb), last, s.tag});
    }
  }
  return e;
}

// Compares the pixels got with want (a prefix of want when `prefix`); returns the mismatches
// (the first few reported, per channel).
int compare(const std::vector<Px>& got, const std::vector<Px>& want, int c_bits, const std::string& what,
            bool prefix = false) {
  int bad = 0;
  if (prefix ? got.size() > want.size() : got.size() != want.size()) {
    FAIL_CHECK(what << ": " << got.size() << " pixels, want " << (prefix ? "at most " : "") << want.size());
    return 1;
  }
  for (size_t i = 0; i < got.size(); ++i) {
    const Px& g = got[i];
    const Px& w = want[i];
    if (g == w) continue;
    if (++bad <= 6) {
      std::ostringstream ch;
      for (int c = 0; c < kChannels; ++c) ch << " " << channel(g.data, c, c_bits) << "/" << channel(w.data, c, c_bits);
      FAIL_CHECK(what << ": pixel " << i << ": channels got/want" << ch.str() << ", last " << g.last << "/" << w.last
                      << ", tag " << g.tag << "/" << w.tag);
    }
  }
  return bad;
}

// A span with random registers and a random colour: each channel 0, the largest code or any
// code; n mostly valid (small, so that the lobes are wide), sometimes any 10-bit code (0 and
// above 1000 included); psi0 mostly within a radian, so that many pixels are lit.
class SpanGen {
 public:
  SpanGen(uint32_t seed, const dev::Format& f, int max_len) : rng_(seed), f_(f), max_len_(max_len) {}
  RgbSpan next() {
    RgbSpan s;
    const uint32_t c_max = static_cast<uint32_t>((uint64_t{1} << f_.c_bits) - 1);
    for (auto& c : s.c) {
      const uint32_t pick = rng_() % 5;
      c = pick == 0 ? 0 : pick == 1 ? c_max : static_cast<uint32_t>(rng_()) & c_max;
    }
    const int64_t one = int64_t{1} << f_.angle_frac;
    s.reg.psi0 = rng_() % 4 == 0 ? uni(-3 * one, 3 * one) : uni(-one / 2, one / 2);
    s.reg.dpsi = uni(-(one >> 6), one >> 6);
    s.reg.n = rng_() % 6 == 0 ? static_cast<uint32_t>(rng_() % (1u << f_.n_bits)) : 1 + static_cast<uint32_t>(rng_() % 40);
    s.reg.len = rng_() % 5 == 0 ? 0 : static_cast<uint32_t>(uni(0, max_len_));
    s.tag = static_cast<uint32_t>(rng_() & 0xffff);
    return s;
  }
  // Arbitrary span bus contents while span_valid_i is low.
  RgbSpan garbage() {
    RgbSpan s;
    for (auto& c : s.c) c = static_cast<uint32_t>(rng_()) & static_cast<uint32_t>((uint64_t{1} << f_.c_bits) - 1);
    s.reg.psi0 = static_cast<int32_t>(rng_());
    s.reg.dpsi = static_cast<int32_t>(rng_());
    s.reg.n = static_cast<uint32_t>(rng_() % (1u << f_.n_bits));
    s.reg.len = static_cast<uint32_t>(rng_() % (1u << f_.len_bits));
    s.tag = static_cast<uint32_t>(rng_() & 0xffff);
    return s;
  }
  bool chance(double p) { return p >= 1.0 || std::uniform_real_distribution<double>(0, 1)(rng_) < p; }

 private:
  int64_t uni(int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng_); }
  std::mt19937 rng_;
  dev::Format f_;
  int max_len_;
};

template <class V>
void drive_span(V& m, const RgbSpan& s, int c_bits) {
  m.span_c_i = pack_c(s.c, c_bits);
  m.span_psi0_i = static_cast<uint32_t>(s.reg.psi0);
  m.span_dpsi_i = static_cast<uint32_t>(s.reg.dpsi);
  m.span_n_i = s.reg.n;
  m.span_len_i = s.reg.len;
  m.span_tag_i = s.tag;
}

template <class V>
void power_up(V& m) {
  m.rst_ni = 1;
  m.clk_i = 0;
  m.span_valid_i = 0;
  m.px_ready_i = 0;
  m.eval();
  reset(m);
}

// The pixel side's rules, cycle by cycle: valid held and the pixel unchanged while stalled,
// the intensity 0 while invalid; the transfers collected.
class PxMonitor {
 public:
  template <class V>
  void sample(const V& m, long cycle) {
    const Px px{static_cast<uint64_t>(m.px_intensity_o), m.px_last_o != 0, static_cast<uint32_t>(m.px_tag_o)};
    if (stalled_ && !m.px_valid_o) fail(cycle, "px_valid_o fell without a transfer");
    else if (stalled_ && !(px == held_)) fail(cycle, "pixel changed while stalled");
    if (!m.px_valid_o && px.data != 0) fail(cycle, "px_intensity_o not 0 while px_valid_o is low");
    if (m.px_valid_o && m.px_ready_i) got.push_back(px);
    stalled_ = m.px_valid_o && !m.px_ready_i;
    held_ = px;
  }
  void restart() { stalled_ = false; }  // after a reset: nothing is held
  std::vector<Px> got;
  std::vector<std::string> errors;

 private:
  void fail(long cycle, const std::string& what) {
    if (errors.size() < 10) errors.push_back("cycle " + std::to_string(cycle) + ": " + what);
  }
  bool stalled_ = false;
  Px held_;
};

// Checks the model's public parameters against the golden model's format: the test must not
// compare a build with another build's model.
template <class P>
void require_format(const dev::Format& f) {
  REQUIRE(static_cast<int>(P::Channels) == kChannels);
  REQUIRE(static_cast<int>(P::CBits) == f.c_bits);
  REQUIRE(static_cast<int>(P::AngleBits) == f.angle_bits);
  REQUIRE(static_cast<int>(P::AngleFrac) == f.angle_frac);
  REQUIRE(static_cast<int>(P::CosDataBits) == f.cos_data_bits);
  REQUIRE(static_cast<int>(P::CoefBits) == f.coef_bits);
  REQUIRE(static_cast<int>(P::PsiMulFrac) == f.psi_mul_frac);
  REQUIRE(static_cast<int>(P::NumBanks) == static_cast<int>(f.banks.size()));
  REQUIRE(static_cast<bool>(P::Blend) == f.blend);
  REQUIRE(kChannels * f.c_bits <= 64);  // the packed colour fits the model's 64-bit ports
}

struct RandomRun {
  long pixels = 0, cycles = 0, lit = 0;  // lit: channel values above 0
  long dropped = 0;                      // pixels in flight at the reset
};

long lit_channels(const std::vector<Px>& px, int c_bits) {
  long n = 0;
  for (const Px& p : px)
    for (int ch = 0; ch < kChannels; ++ch) n += channel(p.data, ch, c_bits) != 0;
  return n;
}

// Random spans, gaps, backpressure and a reset while pixels are in flight; every pixel checked.
template <class V>
RandomRun run_random(const dev::DeviceModel& model, uint32_t seed, double offer_p, double ready_p) {
  const int cb = model.format().c_bits;
  V m;
  power_up(m);
  SpanGen gen(seed, model.format(), 12);
  PxMonitor mon;
  RandomRun res;
  constexpr int kSpansBefore = 200, kSpansAfter = 1500;
  std::vector<RgbSpan> accepted;
  RgbSpan cur = gen.next();
  bool offering = false, reset_done = false, idle_after_reset = false;
  long cycle = 0, expected_pixels = 0;
  for (; cycle < 200000; ++cycle) {
    // The reset: once kSpansBefore spans are in and some of their pixels are still owed.
    if (!reset_done && static_cast<int>(accepted.size()) == kSpansBefore &&
        static_cast<long>(mon.got.size()) < expected_pixels) {
      const Expected e = expect(model, accepted);
      CHECK(compare(mon.got, e.rgb, cb, "before the reset (rgb_pixel)", true) == 0);
      CHECK(compare(mon.got, e.scalar, cb, "before the reset (scalar pixel per channel)", true) == 0);
      res.pixels += static_cast<long>(mon.got.size());
      res.lit += lit_channels(mon.got, cb);
      res.dropped = expected_pixels - static_cast<long>(mon.got.size());
      reset(m);
      reset_done = idle_after_reset = true;
      accepted.clear();
      mon.got.clear();
      mon.restart();
      expected_pixels = 0;
      offering = false;
      cur = gen.next();
    }
    const int target = reset_done ? kSpansAfter : kSpansBefore;
    if (!offering && static_cast<int>(accepted.size()) < target && gen.chance(offer_p)) offering = true;
    drive_span(m, offering ? cur : gen.garbage(), cb);
    m.span_valid_i = offering;
    m.px_ready_i = gen.chance(ready_p);
    m.eval();
    if (idle_after_reset && m.px_valid_o) FAIL_CHECK("cycle " << cycle << ": a pixel after the reset before any span");
    mon.sample(m, cycle);
    const bool accept = offering && m.span_ready_o;
    tick(m);
    if (accept) {
      accepted.push_back(cur);
      expected_pixels += cur.reg.len + 1;
      cur = gen.next();
      offering = false;
      idle_after_reset = false;
    }
    if (reset_done && static_cast<int>(accepted.size()) == kSpansAfter &&
        static_cast<long>(mon.got.size()) == expected_pixels) {
      break;
    }
  }
  REQUIRE(reset_done);
  REQUIRE(static_cast<int>(accepted.size()) == kSpansAfter);
  const Expected e = expect(model, accepted);
  CHECK(compare(e.rgb, e.scalar, cb, "rgb_pixel against the scalar model per channel") == 0);
  CHECK(compare(mon.got, e.rgb, cb, "after the reset (rgb_pixel)") == 0);
  CHECK(compare(mon.got, e.scalar, cb, "after the reset (scalar pixel per channel)") == 0);
  for (const auto& err : mon.errors) FAIL_CHECK("pixel handshake: " << err);
  res.pixels += static_cast<long>(mon.got.size());
  res.lit += lit_channels(mon.got, cb);
  res.cycles = cycle;
  return res;
}

struct Throughput {
  long pixels = 0, first = -1, last = -1, first_accept = -1;
};

// Back-to-back spans of 1 to 4 pixels, span_valid_i always high, px_ready_i always high.
template <class V>
Throughput run_back_to_back(const dev::DeviceModel& model, uint32_t seed, int spans) {
  const int cb = model.format().c_bits;
  V m;
  power_up(m);
  SpanGen gen(seed, model.format(), 3);
  PxMonitor mon;
  Throughput t;
  std::vector<RgbSpan> accepted;
  RgbSpan cur = gen.next();
  long expected_pixels = 0;
  for (long cycle = 0; cycle < 100000; ++cycle) {
    const bool offering = static_cast<int>(accepted.size()) < spans;
    drive_span(m, cur, cb);
    m.span_valid_i = offering;
    m.px_ready_i = 1;
    m.eval();
    mon.sample(m, cycle);
    if (m.px_valid_o) {
      if (t.first < 0) t.first = cycle;
      t.last = cycle;
    }
    const bool accept = offering && m.span_ready_o;
    tick(m);
    if (accept) {
      if (t.first_accept < 0) t.first_accept = cycle;
      accepted.push_back(cur);
      expected_pixels += cur.reg.len + 1;
      cur = gen.next();
    }
    if (static_cast<int>(accepted.size()) == spans && static_cast<long>(mon.got.size()) == expected_pixels) break;
  }
  REQUIRE(static_cast<int>(accepted.size()) == spans);
  const Expected e = expect(model, accepted);
  CHECK(compare(mon.got, e.rgb, cb, "back to back (rgb_pixel)") == 0);
  CHECK(compare(mon.got, e.scalar, cb, "back to back (scalar pixel per channel)") == 0);
  for (const auto& err : mon.errors) FAIL_CHECK("pixel handshake: " << err);
  t.pixels = static_cast<long>(mon.got.size());
  return t;
}

template <class V, class P, class Pipe>
void rgb_stream_tests(const dev::DeviceModel& model, const std::string& build) {
  require_format<P>(model.format());
  SECTION("random spans, gaps, backpressure and a reset mid-stream") {
    uint32_t seed = model.format().blend ? 1000u : 0u;
    for (const double offer_p : {1.0, 0.4}) {
      for (const double ready_p : {1.0, 0.7, 0.3}) {
        const RandomRun r = run_random<V>(model, ++seed, offer_p, ready_p);
        UNSCOPED_INFO(build << ", offer " << offer_p << ", ready " << ready_p << ": " << r.pixels << " pixels x "
                            << kChannels << " channels checked (" << r.lit << " channel values above 0) in "
                            << r.cycles << " cycles, " << r.dropped << " in flight at the reset");
        CHECK(r.dropped > 0);
        CHECK(r.lit > r.pixels / 4);  // enough lit pixels to test the multipliers
      }
    }
  }
  SECTION("one pixel per clock on back-to-back short spans, the scalar build's latency") {
    const Throughput t = run_back_to_back<V>(model, model.format().blend ? 77u : 7u, 400);
    const long clocks = t.last - t.first + 1;
    UNSCOPED_INFO(build << ": " << t.pixels << " pixels in " << clocks << " clocks from the first to the last: "
                        << std::fixed << std::setprecision(2)
                        << static_cast<double>(t.pixels) / static_cast<double>(clocks) << " pixels per clock");
    CHECK(clocks == t.pixels);
    CHECK(t.first - t.first_accept == static_cast<long>(Pipe::StreamLatency));
  }
}

}  // namespace

TEST_CASE("specular_stream Channels = 3, default build: every channel bit-exact, 1 pixel per clock",
          "[rtl][stream][rgb]") {
  const specular::BuildConfig& bc = specular::build_config("default");
  const auto model = specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
  rgb_stream_tests<Vstream_rgb, Vstream_rgb_specular_stream, Vpipeline_rgb_default_specular_pipeline>(model,
                                                                                                      "default");
}

TEST_CASE("specular_stream Channels = 3, single-bank build: every channel bit-exact, 1 pixel per clock",
          "[rtl][stream][rgb]") {
  const auto model = specular::load_device_model(dev::Format{}, specular::kCoefMinimaxHex, specular::kCosHex);
  rgb_stream_tests<Vstream_rgb_single, Vstream_rgb_single_specular_stream, Vpipeline_rgb_single_specular_pipeline>(
      model, "single");
}

TEST_CASE("rgb_pixel: the scalar pixel per channel, C = 0 gives 0, the largest C within the format",
          "[model][rgb]") {
  for (const char* name : {"default", "single"}) {
    const specular::BuildConfig& bc = specular::build_config(name);
    const auto model = specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
    const uint32_t c_max = (1u << bc.f.c_bits) - 1;
    dev::Registers r;
    r.psi0 = -(int64_t{1} << (bc.f.angle_frac - 3));  // -1/8 rad
    r.dpsi = int64_t{1} << (bc.f.angle_frac - 9);
    r.n = 8;
    r.len = 63;
    int lit = 0;
    for (int i = 0; i <= 63; ++i) {
      const dev::RgbC got = model.rgb_pixel(r, {0, c_max, 12345}, i);
      dev::Registers rs = r;
      rs.c = c_max;
      CHECK(got[0] == 0);
      CHECK(got[1] == model.pixel(rs, i));
      rs.c = 12345;
      CHECK(got[2] == model.pixel(rs, i));
      CHECK(got[1] <= c_max);
      lit += got[1] > 0;
      // A code above the format is cut to c_bits, as register 1 latches it.
      CHECK(model.rgb_pixel(r, {c_max + 1, 0, 0}, i)[0] == 0);
    }
    CHECK(lit > 32);
  }
}

TEST_CASE("specular_axis Channels = 3 equals specular_stream Channels = 3 in lock step", "[rtl][axis][rgb]") {
  using RA = Vaxis_rgb_specular_axis;
  // The descriptor {len, n, dpsi, psi0, c} with c 3 x 16 bits; the pixel 48 bits.
  CHECK(static_cast<int>(RA::Channels) == kChannels);
  CHECK(static_cast<int>(RA::SpanDataBits) == 136);
  CHECK(static_cast<int>(RA::PxDataBits) == 48);
  CHECK(static_cast<int>(RA::OffC) == 0);
  CHECK(static_cast<int>(RA::OffPsi0) == 48);
  CHECK(static_cast<int>(RA::OffDpsi) == 80);
  CHECK(static_cast<int>(RA::OffN) == 112);
  CHECK(static_cast<int>(RA::OffLen) == 122);

  const specular::BuildConfig& bc = specular::build_config("default");
  const auto model = specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
  const int cb = model.format().c_bits;
  Vaxis_rgb ax;
  Vstream_rgb st;
  ax.rst_ni = 1;
  ax.clk_i = 0;
  ax.s_axis_span_tvalid = 0;
  ax.m_axis_px_tready = 0;
  ax.eval();
  reset(ax);
  power_up(st);
  SpanGen gen(99, model.format(), 12);
  std::vector<RgbSpan> accepted;
  std::vector<Px> got;
  RgbSpan cur = gen.next();
  bool offering = false;
  int mismatches = 0;
  long expected_pixels = 0, cycle = 0;
  const int kSpans = 150;
  for (; cycle < 100000; ++cycle) {
    if (!offering && static_cast<int>(accepted.size()) < kSpans && gen.chance(0.6)) offering = true;
    const RgbSpan s = offering ? cur : gen.garbage();
    // Bit offsets written out from the layout above; random pad bits [135:133].
    std::array<uint32_t, 5> w{};
    auto put = [&](int lsb, int bits, uint64_t v) {
      for (int b = 0; b < bits; ++b)
        if (v >> b & 1) w[static_cast<size_t>((lsb + b) / 32)] |= 1u << ((lsb + b) % 32);
    };
    put(0, 48, pack_c(s.c, cb));
    put(48, 32, static_cast<uint32_t>(s.reg.psi0));
    put(80, 32, static_cast<uint32_t>(s.reg.dpsi));
    put(112, 10, s.reg.n);
    put(122, 11, s.reg.len);
    put(133, 3, cycle & 7);
    for (size_t i = 0; i < w.size(); ++i) ax.s_axis_span_tdata[i] = w[i];
    ax.s_axis_span_tuser = s.tag;
    ax.s_axis_span_tvalid = offering;
    drive_span(st, s, cb);
    st.span_valid_i = offering;
    ax.m_axis_px_tready = st.px_ready_i = gen.chance(0.7);
    ax.eval();
    st.eval();
    const bool same = ax.s_axis_span_tready == st.span_ready_o && ax.m_axis_px_tvalid == st.px_valid_o &&
                      ax.m_axis_px_tdata == st.px_intensity_o && ax.m_axis_px_tlast == st.px_last_o &&
                      ax.m_axis_px_tuser == st.px_tag_o;
    if (!same && ++mismatches <= 5) FAIL_CHECK("cycle " << cycle << ": specular_axis differs from specular_stream");
    if (ax.m_axis_px_tvalid && ax.m_axis_px_tready)
      got.push_back({static_cast<uint64_t>(ax.m_axis_px_tdata), ax.m_axis_px_tlast != 0,
                     static_cast<uint32_t>(ax.m_axis_px_tuser)});
    const bool accept = offering && ax.s_axis_span_tready;
    tick(ax);
    tick(st);
    if (accept) {
      accepted.push_back(cur);
      expected_pixels += cur.reg.len + 1;
      cur = gen.next();
      offering = false;
    }
    if (static_cast<int>(accepted.size()) == kSpans && static_cast<long>(got.size()) == expected_pixels) break;
  }
  CHECK(mismatches == 0);
  REQUIRE(static_cast<int>(accepted.size()) == kSpans);
  CHECK(compare(got, expect(model, accepted).rgb, cb, "specular_axis (rgb_pixel)") == 0);
  UNSCOPED_INFO("specular_axis: " << got.size() << " pixels x 3 channels in " << cycle << " cycles");
  CHECK(!got.empty());
}
