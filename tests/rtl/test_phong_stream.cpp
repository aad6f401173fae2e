// SPDX-License-Identifier: Apache-2.0
// phong_stream (rtl/competitors/phong/phong_stream.sv) against its golden model (model/device/phong_model.hpp),
// bit for bit, on the geometry span interface (docs/interfaces.md#geometry-span-interface):
// random spans and the hard cases under random span offers, random pixel backpressure and
// random asynchronous resets (a reset drops every span and pixel in flight), and the
// throughput contract (one pixel per clock, l = 0 spans back to back included). Ten
// configurations: n1000 (the default parameters), n64 with constant H, the cancellation-free
// form (PhongFormat::cross) with and without constant H, and both forms at budgets B2, B3 and B4
// (PhongFormat::at_budget, shorter runs).
// The expected pixels come from PhongModel::stream_span of each span the core accepted; the
// handshake rules (valid held, data stable while stalled) are checked every cycle.
#include "Vphong_b2_n1000.h"
#include "Vphong_b3_n1000.h"
#include "Vphong_b4_n1000.h"
#include "Vphong_cross_b2_n1000.h"
#include "Vphong_cross_b3_n1000.h"
#include "Vphong_cross_b4_n1000.h"
#include "Vphong_cross_n1000.h"
#include "Vphong_cross_n1000_consth.h"
#include "Vphong_n1000.h"
#include "Vphong_n64_consth.h"
#include "geo_span.hpp"
#include "phong_model.hpp"
#include "rtl_harness.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

using namespace specular;
using namespace specular::device;
using specular::rtl_test::reset;
using specular::rtl_test::tick;

namespace {

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

// Random spans of every kind the interface allows: mostly short (the pipeline's span
// handling), some long, some with the hard cases (n = 0 or > 1000, zero vectors, N.H <= 0,
// N1 = -N2, vectors at the ends of the code range).
std::vector<GeoSpan> random_spans(const PhongFormat& f, uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const GeoFormat g = geo_format(f);
  const Format cf = c_format(f);
  std::vector<GeoSpan> v;
  for (int k = 0; k < count; ++k) {
    ScanlineInput in;
    in.h1 = random_unit(rng) * (0.5 + 0.5 * u(rng));
    in.he = f.const_h ? in.h1 : glm::normalize(in.h1 + 0.3 * random_unit(rng));
    const double spread = u(rng) < 0.5 ? 0.15 : 1.2;
    in.n1 = glm::normalize(glm::normalize(in.h1) + spread * random_unit(rng)) * (0.6 + 0.4 * u(rng));
    in.n2 = glm::normalize(glm::normalize(in.h1) + spread * random_unit(rng)) * (0.6 + 0.4 * u(rng));
    const double r = u(rng);
    in.l = r < 0.4 ? 0 : r < 0.8 ? static_cast<int>(u(rng) * 6) : r < 0.98 ? static_cast<int>(u(rng) * 200) : 2047;
    in.n = 1 + static_cast<int>(u(rng) * u(rng) * 1000);
    in.is = 0.3 + 1.6 * u(rng);
    GeoSpan s = quantize_geo(in, g, cf, static_cast<uint32_t>(rng()));
    const double h = u(rng);
    if (h < 0.03) s.n = u(rng) < 0.5 ? 0 : 1001 + static_cast<uint32_t>(u(rng) * 22);
    else if (h < 0.05) s.n1 = GeoVec{0, 0, 0};
    else if (h < 0.06) s.he = GeoVec{0, 0, 0};
    else if (h < 0.08) s.n2 = GeoVec{-s.n1[0], -s.n1[1], -s.n1[2]};
    else if (h < 0.10) s.h1 = GeoVec{static_cast<int32_t>(g.vec_min()), static_cast<int32_t>(g.vec_max()), 0};
    else if (h < 0.12) s.n1 = GeoVec{-s.h1[0], -s.h1[1], -s.h1[2]};
    else if (h < 0.20) {
      // Short vectors: the cross form's headroom shift (docs/phong_hw.md#the-cancellation-free-form).
      const int sh = 1 + static_cast<int>(u(rng) * 14);
      GeoVec& a = u(rng) < 0.5 ? s.n1 : s.h1;
      GeoVec& b = &a == &s.n1 ? s.n2 : s.he;
      for (int c = 0; c < 3; ++c) {
        a[c] /= 1 << sh;
        b[c] /= 1 << sh;
      }
    }
    v.push_back(s);
  }
  return v;
}

struct Expected {
  uint32_t intensity;
  bool last;
  uint32_t tag;
};

template <class Model>
struct Bench {
  Model dut;
  PhongModel golden;
  GeoFormat g;
  std::deque<Expected> expect;
  long cycles = 0, pixels = 0, nonzero = 0, accepted = 0, resets = 0, mismatches = 0;
  bool prev_stalled = false;
  uint64_t prev_px = 0;
  std::string error;

  explicit Bench(const PhongFormat& f) : golden(f), g(geo_format(f)) {
    dut.geo_valid_i = 0;
    dut.px_ready_i = 0;
    reset(dut);
  }

  void offer(const GeoSpan& s) {
    dut.geo_n1_i = pack_vec(s.n1, g);
    dut.geo_n2_i = pack_vec(s.n2, g);
    dut.geo_h1_i = pack_vec(s.h1, g);
    dut.geo_he_i = pack_vec(s.he, g);
    dut.geo_n_i = s.n;
    dut.geo_len_i = s.len;
    dut.geo_scale_i = s.scale;
    dut.geo_tag_i = s.tag;
  }

  void fail(const std::string& what) {
    ++mismatches;
    if (error.empty()) error = "cycle " + std::to_string(cycles) + ": " + what;
  }

  // One cycle: inputs set by the caller, then the checks, then the edge. Returns whether the
  // offered span was taken.
  bool cycle(bool valid, bool ready, const GeoSpan* s) {
    dut.geo_valid_i = valid;
    if (s) offer(*s);
    dut.px_ready_i = ready;
    dut.eval();
    const uint64_t px = (uint64_t{dut.px_intensity_o} << 32) | (uint64_t{dut.px_last_o} << 31) | dut.px_tag_o;
    if (prev_stalled && (!dut.px_valid_o || px != prev_px)) fail("px_valid_o or the pixel changed while stalled");
    if (!dut.px_valid_o && dut.px_intensity_o != 0) fail("px_intensity_o not 0 while px_valid_o is low");
    const bool taken = valid && dut.geo_ready_o;
    if (taken) {
      std::vector<StreamPixel> out;
      golden.stream_span(*s, out);
      for (const StreamPixel& p : out) expect.push_back({p.intensity, p.last, p.tag});
      ++accepted;
    }
    if (dut.px_valid_o && ready) {
      if (expect.empty()) {
        fail("a pixel nobody asked for");
      } else {
        const Expected e = expect.front();
        expect.pop_front();
        if (dut.px_intensity_o != e.intensity || static_cast<bool>(dut.px_last_o) != e.last || dut.px_tag_o != e.tag)
          fail("pixel " + std::to_string(pixels) + ": rtl " + std::to_string(dut.px_intensity_o) + " last " +
               std::to_string(dut.px_last_o) + " tag " + std::to_string(dut.px_tag_o) + ", golden " +
               std::to_string(e.intensity) + " last " + std::to_string(e.last) + " tag " + std::to_string(e.tag));
      }
      ++pixels;
      if (dut.px_intensity_o != 0) ++nonzero;
    }
    prev_stalled = dut.px_valid_o && !ready;
    prev_px = px;
    tick(dut);
    ++cycles;
    return taken;
  }

  // The asynchronous reset in the middle of a cycle: everything in flight is dropped.
  void async_reset() {
    dut.rst_ni = 0;
    dut.eval();
    if (dut.px_valid_o) fail("px_valid_o high during reset");
    tick(dut);
    dut.rst_ni = 1;
    dut.eval();
    expect.clear();
    prev_stalled = false;
    ++resets;
  }
};

// Random offers, backpressure and resets over `spans`, then a drain.
template <class Model>
void run_random(const PhongFormat& f, const std::vector<GeoSpan>& spans, double p_valid, double p_ready,
                double p_reset, uint64_t seed) {
  Bench<Model> b(f);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  size_t next = 0;
  bool offering = false;
  while (next < spans.size()) {
    if (u(rng) < p_reset) {
      b.async_reset();
      offering = false;
      continue;
    }
    offering = offering || u(rng) < p_valid;  // a span offered stays offered until taken
    if (b.cycle(offering, u(rng) < p_ready, &spans[next])) {
      ++next;
      offering = false;
    }
  }
  for (long k = 0; k < 200000 && !b.expect.empty(); ++k) b.cycle(false, u(rng) < std::max(p_ready, 0.5), &spans.back());
  for (int k = 0; k < 400; ++k) b.cycle(false, true, &spans.back());  // nothing more may come out
  INFO(b.error);
  INFO("cycles " << b.cycles << ", spans accepted " << b.accepted << ", pixels " << b.pixels << " (" << b.nonzero
                 << " not 0), resets " << b.resets);
  CHECK(b.mismatches == 0);
  CHECK(b.expect.empty());
  CHECK(b.pixels > 1000);
  CHECK(b.nonzero > b.pixels / 4);  // the pixels compared are mostly lit, not zeros
  if (p_reset > 0.0) CHECK(b.resets > 0);
}

template <class Model>
void run_throughput(const PhongFormat& f, int len, int count) {
  Bench<Model> b(f);
  std::vector<GeoSpan> spans = random_spans(f, 77, count);
  for (GeoSpan& s : spans) s.len = static_cast<uint32_t>(len);
  size_t next = 0;
  long first = -1, last = -1;
  while (next < spans.size()) {
    const long px_before = b.pixels;
    if (b.cycle(true, true, &spans[next])) ++next;
    if (b.pixels > px_before) {
      if (first < 0) first = b.cycles;
      last = b.cycles;
    }
  }
  for (int k = 0; k < 400 && !b.expect.empty(); ++k) {
    const long px_before = b.pixels;
    b.cycle(false, true, &spans.back());
    if (b.pixels > px_before) last = b.cycles;
  }
  INFO(b.error);
  REQUIRE(b.mismatches == 0);
  REQUIRE(b.expect.empty());
  const long total = static_cast<long>(count) * (len + 1);
  REQUIRE(b.pixels == total);
  // Every pixel in consecutive cycles: 1.00 pixel per clock, no bubble between spans.
  REQUIRE(last - first + 1 == total);
}

PhongFormat with_const_h(PhongFormat f) {
  f.const_h = true;
  return f;
}

}  // namespace

TEST_CASE("phong_stream n1000: random spans under backpressure and resets, bit-exact", "[phong_stream]") {
  const PhongFormat f = PhongFormat::preset(1000);
  run_random<Vphong_n1000>(f, random_spans(f, 1, 3000), 0.7, 0.7, 0.0005, 11);
}

TEST_CASE("phong_stream n1000: full rate offers and a slow sink, bit-exact", "[phong_stream]") {
  const PhongFormat f = PhongFormat::preset(1000);
  run_random<Vphong_n1000>(f, random_spans(f, 2, 1500), 1.0, 0.3, 0.0, 12);
}

TEST_CASE("phong_stream n1000: one pixel per clock, l = 0 spans back to back", "[phong_stream]") {
  run_throughput<Vphong_n1000>(PhongFormat::preset(1000), 0, 3000);
}

TEST_CASE("phong_stream n1000: one pixel per clock, l = 3 spans back to back", "[phong_stream]") {
  run_throughput<Vphong_n1000>(PhongFormat::preset(1000), 3, 500);
}

TEST_CASE("phong_stream n64 constant H: random spans under backpressure and resets, bit-exact", "[phong_stream]") {
  const PhongFormat f = with_const_h(PhongFormat::preset(64));
  run_random<Vphong_n64_consth>(f, random_spans(f, 3, 3000), 0.7, 0.7, 0.0005, 13);
  run_throughput<Vphong_n64_consth>(f, 0, 1000);
}

TEST_CASE("phong_stream cross n1000: random spans under backpressure and resets, bit-exact", "[phong_stream]") {
  const PhongFormat f = PhongFormat::cross();
  run_random<Vphong_cross_n1000>(f, random_spans(f, 4, 3000), 0.7, 0.7, 0.0005, 14);
  run_random<Vphong_cross_n1000>(f, random_spans(f, 5, 1500), 1.0, 0.3, 0.0, 15);
}

TEST_CASE("phong_stream cross n1000: one pixel per clock, l = 0 and l = 3 spans back to back", "[phong_stream]") {
  run_throughput<Vphong_cross_n1000>(PhongFormat::cross(), 0, 3000);
  run_throughput<Vphong_cross_n1000>(PhongFormat::cross(), 3, 500);
}

TEST_CASE("phong_stream cross n1000 constant H: random spans under backpressure and resets, bit-exact",
          "[phong_stream]") {
  const PhongFormat f = with_const_h(PhongFormat::cross());
  run_random<Vphong_cross_n1000_consth>(f, random_spans(f, 6, 3000), 0.7, 0.7, 0.0005, 16);
  run_throughput<Vphong_cross_n1000_consth>(f, 0, 1000);
}

TEMPLATE_TEST_CASE_SIG("phong_stream at budgets B2, B3 and B4: random spans under backpressure and resets, bit-exact",
                       "[phong_stream]", ((class Model, int Budget, bool Cross), Model, Budget, Cross),
                       (Vphong_b2_n1000, 2, false), (Vphong_b3_n1000, 3, false), (Vphong_b4_n1000, 4, false),
                       (Vphong_cross_b2_n1000, 2, true), (Vphong_cross_b3_n1000, 3, true),
                       (Vphong_cross_b4_n1000, 4, true)) {
  const PhongFormat f = PhongFormat::at_budget(Cross ? PhongForm::cross : PhongForm::dot, "b" + std::to_string(Budget));
  run_random<Model>(f, random_spans(f, 20 + Budget, 1000), 0.7, 0.7, 0.001, 30 + Budget);
  run_throughput<Model>(f, 0, 500);
}
