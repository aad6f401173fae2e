// SPDX-License-Identifier: Apache-2.0
// System stage of the regression (system_stage.hpp).
#include "system_stage.hpp"

#include "harness.hpp"  // before the V*.h: wraps the Verilator headers in a warning guard

#include "Vspecular_system.h"
#include "system_setup_ii.inc"  // SPECULAR_SYSTEM_SETUP_II (sim/CMakeLists.txt)
#include "Vspecular_system_ii16.h"
#include "system_blend.inc"  // SPECULAR_SYSTEM_BLEND: SetupII 16 at each blend build (sim/CMakeLists.txt)
#if SPECULAR_SYSTEM_SETUP_II
#include "Vspecular_system_ii32.h"
#include "Vspecular_system_ii64.h"
#include "Vspecular_system_ii8.h"
#endif
#include "geo_cases.hpp"
#include "geo_span.hpp"
#include "metrics.hpp"
#include "setup_batch.hpp"
#include "setup_contract.hpp"
#include "setup_fixed.hpp"
#include "verilated_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

namespace specular::sim {
namespace {

// One expected pixel: the golden models' value, and the end-to-end reference with its allowance.
struct Pixel {
  device::StreamPixel px;
  double ref = 0.0, allow = 0.0, rel_ref = -1.0;  // rel_ref: the reference where the relative error counts
  bool check_e2e = false;
};

template <class V>
class Bench {
 public:
  Bench(const BuildConfig& bc, const device::DeviceModel& dm) : bc_(bc), dm_(dm), vm_("specular_system"), top_(vm_.top()) {
    vm_.power_up();
  }
  V* top() const { return top_; }
  void reset() {
    top_->rst_ni = 0;
    top_->eval();
    tick();
    top_->rst_ni = 1;
    top_->eval();
  }
  void tick() {
    top_->clk_i = 1;
    top_->eval();
    top_->clk_i = 0;
    top_->eval();
    ++cycle_;
  }
  uint64_t cycle() const { return cycle_; }
  void drive(const device::GeoSpan& g) {
    const device::GeoFormat& gf = geo_cases::kGeo;
    top_->geo_n1_i = device::pack_vec(g.n1, gf);
    top_->geo_n2_i = device::pack_vec(g.n2, gf);
    top_->geo_h1_i = device::pack_vec(g.h1, gf);
    top_->geo_he_i = device::pack_vec(g.he, gf);
    top_->geo_n_i = static_cast<uint16_t>(g.n);
    top_->geo_len_i = static_cast<uint16_t>(g.len);
    top_->geo_scale_i = static_cast<uint16_t>(g.scale);
    top_->geo_tag_i = static_cast<uint16_t>(g.tag);
  }

  // The expected pixels of a span, and its setup error into `st`.
  void expect(const device::GeoSpan& g, bool accuracy, SystemRunStats& st, std::deque<Pixel>& out) const {
    const device::Format& f = bc_.f;
    const host::fixed::Result r = host::fixed::setup_fixed(g, geo_cases::kGeo, f);
    std::vector<device::StreamPixel> px;
    dm_.stream_span(r.span, px);
    if (!accuracy) {
      for (const auto& p : px) out.push_back({p});
      return;
    }
    const ScanlineInput in = device::geo_input(g, geo_cases::kGeo, f);
    const host::ContractCheck c = host::check_contract(
        g, r.status, {r.trace.opposite_normals, r.trace.flat, r.trace.opposite_halfway}, r.span.reg, geo_cases::kGeo, f);
    if (!c.decisions_equal && st.status_mismatches++ == 0)
      st.first_errors.push_back("setup decisions differ from the contract's reference outside the guard bands");
    st.setup_violations += !c.pixels.ok();
    st.setup_worst = std::max(st.setup_worst, c.pixels.worst);
    st.setup_rel = std::max(st.setup_rel, c.pixels.max_rel_epicenter);
    st.setup_lsb = std::max(st.setup_lsb, c.pixels.max_abs_lsb);
    const ScanlineSetup& s = c.ref_setup;
    const bool c_sat = device::load_registers(s, in.n, in.l, f).c_saturated;
    st.c_saturated_spans += c_sat;
    const double lsb = std::ldexp(1.0, -f.c_frac), n = in.n;
    const bool valid_n = s.status != SetupStatus::invalid_input;
    const double xe = valid_n ? epicenter_end(n) : 0.0;
    for (size_t i = 0; i < px.size(); ++i) {
      Pixel p{px[i]};
      p.check_e2e = !c_sat;
      p.ref = valid_n ? pixel_blinn(s, n, static_cast<int>(i)) : 0.0;
      const double psi = pixel_psi(s, static_cast<int>(i));
      const bool epi = valid_n && std::abs(psi) <= xe;
      const bool n1_abs = n == 1.0 && p.ref < bc_.budget.n1_min_ref_lsb * lsb;
      if (epi && !n1_abs) {
        p.allow = bc_.budget.rel_epicenter * p.ref + lsb;
        if (p.ref >= 0x1p-10) p.rel_ref = p.ref;
      } else {
        p.allow = bc_.budget.abs_lobe * std::min(s.C, 2.0) + lsb;
      }
      out.push_back(p);
    }
  }

 private:
  const BuildConfig& bc_;
  const device::DeviceModel& dm_;
  VerilatedModel<V> vm_;
  V* top_;
  uint64_t cycle_ = 0;
};

void error(SystemRunStats& st, const std::string& what) {
  ++st.protocol_errors;
  if (st.first_errors.size() < 5) st.first_errors.push_back(what);
}

// Offers `spans` in order (each held until accepted) with the probabilities per clock of an
// offer, of px_ready_i and of a reset; checks every pixel transfer; ends draining.
template <class V>
SystemRunStats run(Bench<V>& b, int setup_ii, const std::string& name, const std::vector<device::GeoSpan>& spans,
                   bool accuracy, double p_valid, double p_ready, double p_reset, uint64_t seed) {
  SystemRunStats st;
  st.name = name;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double lsb = 0x1p-15;
  std::deque<Pixel> expected;
  b.reset();
  V* t = b.top();
  size_t next = 0;
  bool offering = false, stalled = false;
  device::StreamPixel held{};
  uint64_t first_accept = 0, first_px = 0, last_px = 0;
  bool any_accept = false, any_px = false;
  uint64_t guard = 0;
  while (next < spans.size() || !expected.empty()) {
    if (!offering && next < spans.size() && (p_valid >= 1.0 || u01(rng) < p_valid)) offering = true;
    t->geo_valid_i = offering;
    if (offering) b.drive(spans[next]);
    t->px_ready_i = next >= spans.size() || p_ready >= 1.0 || u01(rng) < p_ready;
    t->eval();
    const device::StreamPixel got{t->px_intensity_o, t->px_last_o != 0, t->px_tag_o};
    if (stalled && (!t->px_valid_o || !(got == held))) error(st, "px_valid_o or the pixel changed while stalled");
    stalled = t->px_valid_o && !t->px_ready_i;
    held = got;
    if (t->px_valid_o && t->px_ready_i) {
      if (!any_px) first_px = b.cycle(), any_px = true;
      last_px = b.cycle();
      if (expected.empty()) {
        error(st, "a pixel without a span");
      } else {
        const Pixel& e = expected.front();
        ++st.pixels;
        if (!(got == e.px) && st.mismatches++ < 5)
          st.first_errors.push_back("pixel " + std::to_string(st.pixels) + ": intensity " + std::to_string(got.intensity) +
                                    " last " + std::to_string(got.last) + " tag " + std::to_string(got.tag) +
                                    ", golden " + std::to_string(e.px.intensity) + " " + std::to_string(e.px.last) + " " +
                                    std::to_string(e.px.tag));
        if (accuracy && e.check_e2e) {
          ++st.e2e_pixels;
          const double err = std::abs(got.intensity * lsb - e.ref);
          st.e2e_worst = std::max(st.e2e_worst, err / e.allow);
          st.e2e_violations += err > e.allow;
          st.e2e_lsb = std::max(st.e2e_lsb, err / lsb);
          if (e.rel_ref > 0) st.e2e_rel = std::max(st.e2e_rel, err / e.rel_ref);
        }
        expected.pop_front();
      }
    }
    const bool accept = offering && t->geo_ready_o;
    b.tick();
    if (accept) {
      if (!any_accept) first_accept = b.cycle() - 1, any_accept = true;
      b.expect(spans[next], accuracy, st, expected);
      ++st.spans, ++next, offering = false;
    }
    if (p_reset > 0.0 && u01(rng) < p_reset) {
      b.reset();
      expected.clear();
      stalled = false;
      ++st.resets;
    }
    // A span takes at most SetupII clocks plus its pixels' (times 4: gaps and backpressure).
    if (++guard > static_cast<uint64_t>(4 + setup_ii) * (spans.size() + st.pixels) + 100000) {
      error(st, "the system did not drain");
      break;
    }
  }
  st.cycles_fill = any_px ? last_px - first_accept + 1 : 0;
  st.cycles_steady = any_px ? last_px - first_px + 1 : 0;
  return st;
}

}  // namespace

bool SystemStats::ok() const {
  if (runs.empty()) return false;
  for (const auto& r : runs)
    if (!r.ok()) return false;
  return true;
}

namespace {

template <class V>
SystemStats run_all(const std::vector<LoadedScene>& scenes, const BuildConfig& bc, uint64_t seed, uint64_t random_spans,
                    int setup_ii) {
  const auto t0 = std::chrono::steady_clock::now();
  const device::DeviceModel dm = load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
  Bench<V> b(bc, dm);
  SystemStats out;
  out.setup_ii = setup_ii;
  const uint32_t tag_mask = (1u << geo_cases::kGeo.tag_bits) - 1;
  for (const LoadedScene& ls : scenes) {
    std::vector<device::GeoSpan> spans;
    spans.reserve(ls.raster.spans.size());
    for (size_t i = 0; i < ls.raster.spans.size(); ++i)
      spans.push_back(device::quantize_geo(ls.raster.spans[i].setup_in, geo_cases::kGeo, bc.f,
                                           static_cast<uint32_t>(i) & tag_mask));
    out.runs.push_back(run(b, setup_ii, ls.scene.name, spans, true, 1.0, 1.0, 0.0, seed));
  }
  // One-pixel spans back to back.
  std::vector<device::GeoSpan> l0 = geo_cases::random_geo_spans(20000, seed + 1);
  for (auto& g : l0) g.len = 0;
  out.runs.push_back(run(b, setup_ii, "l0", l0, true, 1.0, 1.0, 0.0, seed + 2));
  if (random_spans > 0) {
    std::vector<device::GeoSpan> rnd = geo_cases::random_geo_spans(random_spans, seed + 3);
    const auto hard = geo_cases::hard_cases();
    for (size_t i = 0; i < hard.size() && i < rnd.size(); ++i) rnd[(i * 7919) % rnd.size()] = hard[i].g;
    // Bit-exact under gaps, backpressure and resets (the accuracy is the scenes' and l0's).
    out.runs.push_back(run(b, setup_ii, "random", rnd, false, 0.8, 0.7, 2e-5, seed + 4));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

bool system_setup_ii_built(int setup_ii) {
  return setup_ii == 1 || setup_ii == 16 || (SPECULAR_SYSTEM_SETUP_II && (setup_ii == 8 || setup_ii == 32 || setup_ii == 64));
}

SystemStats run_system_stage(const std::vector<LoadedScene>& scenes, const BuildConfig& bc, uint64_t seed,
                             uint64_t random_spans, int setup_ii) {
  if (bc.name == "default") {
#if SPECULAR_SYSTEM_SETUP_II
    if (setup_ii == 8) return run_all<Vspecular_system_ii8>(scenes, bc, seed, random_spans, setup_ii);
    if (setup_ii == 32) return run_all<Vspecular_system_ii32>(scenes, bc, seed, random_spans, setup_ii);
    if (setup_ii == 64) return run_all<Vspecular_system_ii64>(scenes, bc, seed, random_spans, setup_ii);
#endif
    if (setup_ii == 16) return run_all<Vspecular_system_ii16>(scenes, bc, seed, random_spans, setup_ii);
    if (setup_ii != 1) throw std::invalid_argument("specular_system at SetupII " + std::to_string(setup_ii) + " is not built");
    return run_all<Vspecular_system>(scenes, bc, seed, random_spans, setup_ii);
  }
  // The other blend builds' systems are verilated at SetupII 16 only, with their own parameters.
#define SPECULAR_BLEND_SYSTEM(id, cfg_name) \
  if (bc.name == cfg_name && setup_ii == 16) return run_all<Vspecular_system_ii16_##id>(scenes, bc, seed, random_spans, setup_ii);
  SPECULAR_SYSTEM_BLEND(SPECULAR_BLEND_SYSTEM)
#undef SPECULAR_BLEND_SYSTEM
  throw std::invalid_argument("specular_system is built for the default build (SetupII 1 and 16, 8, 32 and 64 with the "
                              "option) and for the other blend builds at SetupII 16, not " + bc.name + " at SetupII " +
                              std::to_string(setup_ii));
}

void print_system_summary(const SystemStats& s) {
  std::printf("\nSystem stage: specular_system, the setup at SetupII %d (setup in hardware -> specular_stream), geometry spans to pixels, %.1f s\n"
              "  bit-exact against setup_fixed + DeviceModel::stream; setup error = fixed-point setup against the scalar\n"
              "  double setup under the hardware rule (host::check_contract, 0.01 %% + 1 LSB); end to end = RTL pixels against\n"
              "  C cos^n(psi_i) of that setup (device budget + 1 LSB); px/clock with px_ready_i high (fill: from the first\n"
              "  accept; steady: first to last pixel)\n",
              s.setup_ii, s.seconds);
  std::printf("  %-14s %8s %9s %5s %5s %9s %9s %10s %8s %10s %8s %6s\n", "run", "spans", "pixels", "mism", "prot",
              "px/clk", "px/clk", "setup rel", "setup", "e2e rel", "e2e", "e2e");
  std::printf("  %-14s %8s %9s %5s %5s %9s %9s %10s %8s %10s %8s %6s\n", "", "", "", "", "", "fill", "steady",
              "epicenter", "LSB", "epicenter", "LSB", "worst");
  for (const auto& r : s.runs) {
    std::printf("  %-14s %8llu %9llu %5llu %5llu %9.4f %9.4f %10.2e %8.3f %10.2e %8.3f %6.3f%s\n", r.name.c_str(),
                (unsigned long long)r.spans, (unsigned long long)r.pixels, (unsigned long long)r.mismatches,
                (unsigned long long)r.protocol_errors, r.px_per_clock_fill(), r.px_per_clock_steady(), r.setup_rel,
                r.setup_lsb, r.e2e_rel, r.e2e_lsb, r.e2e_worst, r.resets ? (" (" + std::to_string(r.resets) + " resets)").c_str() : "");
    for (const auto& m : r.first_errors) std::printf("    %s: %s\n", r.name.c_str(), m.c_str());
    if (r.status_mismatches || r.setup_violations || r.e2e_violations)
      std::printf("    %s: %llu status mismatches, %llu spans over the setup tolerance, %llu pixels over the end-to-end budget\n",
                  r.name.c_str(), (unsigned long long)r.status_mismatches, (unsigned long long)r.setup_violations,
                  (unsigned long long)r.e2e_violations);
  }
  std::printf("  system stage: %s\n", s.ok() ? "PASS" : "FAIL");
}

}  // namespace specular::sim
