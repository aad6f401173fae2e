// SPDX-License-Identifier: Apache-2.0
// Phong stage of the regression (sim/phong_stage.hpp).
#include "phong_stage.hpp"

#include "Vphong_cross_scene.h"
#include "Vphong_scene.h"
#include "metrics.hpp"
#include "phong_error.hpp"
#include "phong_model.hpp"
#include "clocking.hpp"
#include "verilated_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>

namespace specular::sim {

namespace {

using device::GeoSpan;
using device::PhongFormat;

void note(PhongSceneStats& s, const std::string& what) {
  if (s.failures.size() < 8) s.failures.push_back(s.name + ": " + what);
}

// One form: f is the format the model was verilated with (its configuration's -G flags).
template <class Model>
void run_form(const std::vector<LoadedScene>& scenes, const std::string& config, const PhongFormat& f,
              std::vector<PhongSceneStats>& out) {
  const device::PhongModel golden(f);
  const device::GeoFormat g = device::geo_format(f);
  const device::Format cf = device::c_format(f);
  const double lsb = std::ldexp(1.0, -f.c_frac);
  for (const LoadedScene& ls : scenes) {
    const auto t0 = std::chrono::steady_clock::now();
    PhongSceneStats st;
    st.name = ls.scene.name;
    st.config = config;
    VerilatedModel<Model> vm("phong_stream");
    Model& m = *vm.top();
    vm.power_up();
    m.geo_valid_i = 0;
    m.px_ready_i = 1;
    m.rst_ni = 0;
    m.eval();
    tick(m);
    m.rst_ni = 1;
    m.eval();
    std::vector<GeoSpan> spans;
    spans.reserve(ls.raster.spans.size());
    for (size_t k = 0; k < ls.raster.spans.size(); ++k)
      spans.push_back(device::quantize_geo(ls.raster.spans[k].setup_in, g, cf, static_cast<uint32_t>(k)));
    // Expected pixels (golden model) with their references, in stream order.
    struct Px {
      device::StreamPixel p;
      uint32_t span;
      int i;
    };
    std::deque<Px> expect;
    size_t next = 0;
    const uint64_t limit = 4 * (ls.raster.stats.shaded_pixels + spans.size()) + 10000;
    while ((next < spans.size() || !expect.empty()) && st.cycles < limit) {
      const bool offer = next < spans.size();
      if (offer) {
        const GeoSpan& s = spans[next];
        m.geo_valid_i = 1;
        m.geo_n1_i = device::pack_vec(s.n1, g);
        m.geo_n2_i = device::pack_vec(s.n2, g);
        m.geo_h1_i = device::pack_vec(s.h1, g);
        m.geo_he_i = device::pack_vec(s.he, g);
        m.geo_n_i = s.n;
        m.geo_len_i = s.len;
        m.geo_scale_i = s.scale;
        m.geo_tag_i = s.tag & ((1U << f.tag_bits) - 1U);
      } else {
        m.geo_valid_i = 0;
      }
      m.eval();
      if (offer && m.geo_ready_o) {
        std::vector<device::StreamPixel> px;
        golden.stream_span(spans[next], px);
        for (size_t i = 0; i < px.size(); ++i) expect.push_back({px[i], static_cast<uint32_t>(next), static_cast<int>(i)});
        ++next;
        ++st.spans;
      }
      if (m.px_valid_o) {
        if (expect.empty()) {
          ++st.mismatches;
          note(st, "a pixel nobody asked for");
        } else {
          const Px e = expect.front();
          expect.pop_front();
          if (m.px_intensity_o != e.p.intensity || static_cast<bool>(m.px_last_o) != e.p.last || m.px_tag_o != e.p.tag) {
            if (st.mismatches < 4)
              note(st, "mismatch span " + std::to_string(e.span) + " pixel " + std::to_string(e.i) + ": rtl " +
                           std::to_string(m.px_intensity_o) + " golden " + std::to_string(e.p.intensity));
            ++st.mismatches;
          }
          // The error of the RTL's pixel against double per-pixel Phong.
          const GeoSpan& s = spans[e.span];
          double cosv = 0.0;
          const double ref = device::phong_exact(s, f, e.i, &cosv);
          const double truth = phong_truth(device::geo_input(s, g, cf), e.i);
          const double got = m.px_intensity_o * lsb;
          const double c = s.scale * lsb;
          const bool epi = cosv > 0.0 && std::acos(cosv) <= epicenter_end(static_cast<double>(s.n)) &&
                           s.n >= 1 && s.n <= 1000;
          auto measure = [&](double r, double& rel, double& abs, bool count) {
            const double err = std::abs(got - r);
            const double allow = std::max(0.0, err - lsb);
            if (c > 0.0) abs = std::max(abs, allow / c);
            if (count && err > 0.01 * c + lsb) {
              if (st.abs_violations < 2) note(st, "absolute error over budget at span " + std::to_string(e.span));
              ++st.abs_violations;
            }
            if (epi && r >= 4 * lsb) {
              rel = std::max(rel, allow / r);
              if (count && err > 1e-3 * r + lsb) {
                if (st.rel_violations < 2) note(st, "epicenter error over budget at span " + std::to_string(e.span));
                ++st.rel_violations;
              }
            }
          };
          if (epi) ++st.epicenter_pixels;
          measure(ref, st.rel_lsb, st.abs_lsb, true);
          measure(truth, st.rel_lsb_truth, st.abs_lsb_truth, false);
        }
        ++st.pixels;
      }
      tick(m);
      ++st.cycles;
    }
    if (!expect.empty()) note(st, std::to_string(expect.size()) + " pixels never came out");
    if (st.pixels == 0) note(st, "no pixels");
    st.mismatches += expect.size();
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.push_back(std::move(st));
  }
}

}  // namespace

std::vector<PhongSceneStats> run_phong_stage(const std::vector<LoadedScene>& scenes) {
  std::vector<PhongSceneStats> out;
  run_form<Vphong_scene>(scenes, "n1000", PhongFormat::preset(1000), out);
  run_form<Vphong_cross_scene>(scenes, "cross_n1000", PhongFormat::cross(), out);
  return out;
}

void print_phong_table(const std::vector<PhongSceneStats>& stats) {
  std::printf("\nPhong stage (phong_stream: n1000 = %s, cross_n1000 = %s; every span back to back;\n"
              "error against per-pixel Phong in double, (|err| - 1 LSB)^+ relative in the epicenter and absolute / C):\n",
              PhongFormat::preset(1000).describe().c_str(), PhongFormat::cross().describe().c_str());
  std::printf("| configuration | scene | spans | pixels | clocks | clocks/pixel | mismatches | epicenter px | max rel epi | max abs / C "
              "| vs phong_truth rel / abs | over budget rel / abs | wall s |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& s : stats)
    std::printf("| %s | %s | %llu | %llu | %llu | %.4f | %llu | %llu | %.3e | %.3e | %.3e / %.3e | %llu / %llu | %.2f |\n",
                s.config.c_str(), s.name.c_str(), (unsigned long long)s.spans, (unsigned long long)s.pixels,
                (unsigned long long)s.cycles, s.pixels ? double(s.cycles) / double(s.pixels) : 0.0,
                (unsigned long long)s.mismatches, (unsigned long long)s.epicenter_pixels, s.rel_lsb, s.abs_lsb,
                s.rel_lsb_truth, s.abs_lsb_truth, (unsigned long long)s.rel_violations,
                (unsigned long long)s.abs_violations, s.seconds);
}

}  // namespace specular::sim
