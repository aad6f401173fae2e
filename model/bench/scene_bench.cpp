// SPDX-License-Identifier: Apache-2.0
// scene_bench: the speed axis per scene, setup included (docs/system.md).
//
//   scene_bench [--json FILE] [--reps R] [--min-time S] [--break-even-spans N] [--max-len L]
//               [--no-break-even] [--fpga-figures FILE] SCENE.json...
//
// For each scene: rasterize (not timed), order the spans by light and material (a renderer
// draws material by material; both methods get the same order), build each method's input
// arrays from the raster (not timed: what the rasterizer hands over per span), then time
// shading ALL spans of all lights by each method (model/bench/shade_spans.hpp):
//   device        host::setup_batch (SpanBatch -> register codes) + DeviceShader::shade
//                 (device_span's float method across spans), SIMD as device_span
//   phong_sleef   per-pixel Phong across spans, SLEEF powf8 (AVX2); per-span preparation timed
//   phong_scalar  the same with libm powf
//   pow_cos       host::setup_scalar (scanline_setup + load_registers) + pow_cos_span per span
// and, beside them, the methods at one instruction set ("isa_matched"): setup_batch's automatic
// path takes AVX-512 where the CPU has it while the shaders above are AVX2, so also the device
// with its setup held to AVX2, and device and phong_sleef both built for AVX-512. The headline
// ratio ("best_isa") is device against phong_sleef both at the best instruction set of the
// CPU: AVX-512 where it has it, else AVX2, else the x86-64 baseline (then "device" and
// "phong_sleef" above, which are that already). The mixed figure stays as "speedup_vs_phong_sleef",
// and, for the host-feeding figures, setup_batch alone (M spans per second on this core)
// against what the streaming core consumes at the HX8K Fmax of `make fpga` (one pixel per
// clock: Fmax / mean pixels per span), read from docs/fpga_figures.json.
//
// The break-even span length: synthetic spans (host::random_spans_of_length, He = H1: a
// directional light and an orthographic camera, so Phong's H is constant) of l = 0..L, device
// (setup included) against phong_sleef, ns per pixel.
//
// Timing: the methods take turns (one sample each per round, R rounds), each sample repeats
// the whole scene until it lasts --min-time seconds of this thread's CPU time
// (CLOCK_THREAD_CPUTIME_ID: time the thread was descheduled by other jobs does not count);
// the figure is the median over the rounds. Exit 2 on bad arguments or an unreadable scene.
#include "cli_parse.hpp"
#include "device_model.hpp"
#include "raster.hpp"
#include "scene.hpp"
#include "setup_batch.hpp"
#include "shade_spans.hpp"
#include "span_shade.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#ifndef SPECULAR_FPGA_FIGURES
#define SPECULAR_FPGA_FIGURES "docs/fpga_figures.json"
#endif

using json = nlohmann::json;
using namespace specular;

namespace {

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Method {
  std::string name;
  std::function<void()> run;
  double items = 1;  // pixels or spans per run
  int iters = 1;     // runs per sample (calibrated)
  std::vector<double> samples;  // ns per item
  Method(std::string n, std::function<void()> f, double count) : name(std::move(n)), run(std::move(f)), items(count) {}
  double median() const {
    std::vector<double> s = samples;
    std::sort(s.begin(), s.end());
    const size_t m = s.size();
    return m % 2 ? s[m / 2] : 0.5 * (s[m / 2 - 1] + s[m / 2]);
  }
};

// Interleaved rounds; see the header.
void time_methods(std::vector<Method>& ms, int reps, double min_time) {
  for (Method& m : ms) {  // warm-up and calibration
    m.run();
    int it = 1;
    for (;;) {
      const double t0 = thread_seconds();
      for (int i = 0; i < it; ++i) m.run();
      const double dt = thread_seconds() - t0;
      if (dt >= min_time || it >= (1 << 24)) break;
      it = dt > 0 ? std::max(it + 1, static_cast<int>(it * 1.2 * min_time / dt)) : it * 10;
    }
    m.iters = it;
    m.samples.clear();
  }
  for (int r = 0; r < reps; ++r)
    for (Method& m : ms) {
      const double t0 = thread_seconds();
      for (int i = 0; i < m.iters; ++i) m.run();
      m.samples.push_back((thread_seconds() - t0) * 1e9 / (m.items * m.iters));
    }
}

double stream_fmax_mhz(const std::string& path, std::string& source) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  const json j = json::parse(f);
  // The default configuration's entry: a --label run's entry names its configuration in
  // "config" (rtl/fpga/README.md#how-to-run), the default's has none.
  for (const json& r : j.at("runs"))
    if (r.at("core") == "specular_stream" && !r.contains("config") &&
        r.at("part").get<std::string>().rfind("HX8K", 0) == 0) {
      source = path + ": specular_stream " + r.at("part").get<std::string>();
      return r.at("fmax_mhz").get<double>();
    }
  throw std::runtime_error(path + " has no specular_stream HX8K run");
}

// "avx512", "avx2" or "baseline": the widest instruction set both methods have here.
std::string best_isa() {
  if (!cpu_has_avx2()) return "baseline";
  return cpu_has_avx512() ? "avx512" : "avx2";
}

std::string simd_description() {
  const bool avx512 = cpu_has_avx512();
  // Built with append: GCC 12 warns falsely (-Wrestrict) on operator+ chains of strings.
  const std::string shade = to_string(resolve(SimdPath::automatic));
  std::string s("setup_batch: ");
  s.append(avx512 ? "avx512" : shade).append(" (SimdPath::automatic); shading (device, phong_sleef): ").append(shade);
  s.append(shade == "avx2" ? " (phong_sleef: SLEEF Sleef_powf8_u10avx2)" : " (no AVX2: phong_sleef runs the libm path)");
  return s;
}

// The largest |a - b| over the pixels, and over pixels where both are finite.
template <class A, class B>
double max_abs_diff(const A& a, const B& b, size_t count) {
  double w = 0.0;
  for (size_t i = 0; i < count; ++i) w = std::max(w, std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
  return w;
}

// The device method and phong_sleef at one instruction set each: setup_batch's automatic path
// takes AVX-512 where the CPU has it, while device and phong_sleef shade with AVX2. AVX2
// throughout: the setup held to AVX2; AVX-512 throughout: both shaders built for AVX-512
// (SLEEF powf16 for Phong). The methods shade into dev and phong; the pointed-to objects
// outlive the methods.
void add_isa_methods(std::vector<Method>& ms, const host::SpanBatch* batch, const device::Format* f,
                     host::RegisterBatch* regs, const host::DeviceShader* shader, const host::PhongSpans* ps, float* dev,
                     float* phong, double np) {
  if (!cpu_has_avx2()) return;
  ms.push_back({"device_avx2", [=] { host::setup_batch(*batch, *f, *regs, SimdPath::avx2); shader->shade(*regs, dev, SimdPath::avx2); }, np});
  if (!cpu_has_avx512()) return;
  ms.push_back({"device_avx512", [=] { host::setup_batch(*batch, *f, *regs); shader->shade_avx512(*regs, dev); }, np});
  ms.push_back({"phong_sleef_avx512", [=] { host::shade_phong_avx512(*ps, phong); }, np});
}

json bench_scene(const std::string& path, int reps, double min_time, double fmax_mhz) {
  const Scene scene = load_scene(path);
  const Raster raster = rasterize(scene);
  const std::vector<Span> spans = host::order_for_shading(raster.spans);
  const device::Format f;
  host::SpanBatch batch;
  batch.reserve(spans.size());
  for (const Span& s : spans) batch.push_back(s.setup_in);
  const host::PhongSpans ps = host::phong_spans(scene, spans);
  const size_t pixels = ps.pixels();
  const double mean_span = spans.empty() ? 0.0 : static_cast<double>(pixels) / static_cast<double>(spans.size());

  static const host::DeviceShader shader(f);
  host::RegisterBatch regs, regs_scalar, regs_fixed;
  host::setup_batch(batch, f, regs_fixed);
  std::vector<float> out_dev(pixels + 8), out_ps(pixels + 8), out_pl(pixels + 8), out_shade(pixels + 8);
  std::vector<double> out_pc(pixels + 8);

  const double np = static_cast<double>(pixels), ns = static_cast<double>(spans.size());
  std::vector<Method> ms;
  ms.push_back({"device", [&] { host::setup_batch(batch, f, regs); shader.shade(regs, out_dev.data()); }, np});
  ms.push_back({"phong_sleef", [&] { host::shade_phong(ps, out_ps.data(), SimdPath::automatic); }, np});
  ms.push_back({"phong_scalar", [&] { host::shade_phong(ps, out_pl.data(), SimdPath::scalar); }, np});
  ms.push_back({"pow_cos", [&] { host::setup_scalar(batch, f, regs_scalar); host::shade_pow_cos(regs_scalar, f, out_pc.data()); }, np});
  // The device method's two parts alone: setup per span, shading per pixel.
  ms.push_back({"setup_batch", [&] { host::setup_batch(batch, f, regs); }, ns});
  ms.push_back({"device_shade", [&] { shader.shade(regs_fixed, out_shade.data()); }, np});
  add_isa_methods(ms, &batch, &f, &regs, &shader, &ps, out_dev.data(), out_ps.data(), np);
  if (pixels > 0) time_methods(ms, reps, min_time);
  std::map<std::string, double> t;
  for (const Method& m : ms) t[m.name] = pixels > 0 ? m.median() : 0.0;

  json j;
  j["scene"] = scene.name;
  j["path"] = path;
  j["spans"] = spans.size();
  j["pixels"] = pixels;
  j["mean_span"] = mean_span;
  j["spans_l0"] = raster.stats.spans_l0;
  j["spans_l1"] = raster.stats.spans_l1;
  j["max_l"] = raster.stats.max_l;
  j["lights"] = json::array();
  for (const host::PhongGroup& g : ps.groups) j["lights"].push_back(g.constant_h ? "constant H" : "per-pixel H");
  j["materials"] = scene.materials.size();
  json nsp, ratio;
  for (const char* k : {"device", "phong_sleef", "phong_scalar", "pow_cos"}) {
    nsp[k] = t[k];
    ratio[k] = t[k] > 0 ? t["phong_sleef"] / t[k] : 0.0;  // > 1: faster than phong_sleef
  }
  j["ns_per_pixel"] = nsp;
  j["speedup_vs_phong_sleef"] = ratio;
  j["device_setup_ns_per_span"] = t["setup_batch"];
  j["device_setup_ns_per_pixel"] = t["setup_batch"] * ns / std::max(np, 1.0);
  j["device_shade_ns_per_pixel"] = t["device_shade"];
  json isa = json::object();
  const bool avx2 = cpu_has_avx2(), avx512 = avx2 && cpu_has_avx512();
  if (avx2)
    isa["avx2"] = {{"device", t["device_avx2"]}, {"phong_sleef", t["phong_sleef"]},
                   {"speedup", t["device_avx2"] > 0 ? t["phong_sleef"] / t["device_avx2"] : 0.0}};
  if (avx512)
    isa["avx512"] = {{"device", t["device_avx512"]}, {"phong_sleef", t["phong_sleef_avx512"]},
                     {"speedup", t["device_avx512"] > 0 ? t["phong_sleef_avx512"] / t["device_avx512"] : 0.0}};
  j["isa_matched"] = isa;
  // The headline: both methods at the best instruction set of this CPU.
  const std::string best = best_isa();
  const double bd = best == "baseline" ? t["device"] : isa[best]["device"].get<double>();
  const double bp = best == "baseline" ? t["phong_sleef"] : isa[best]["phong_sleef"].get<double>();
  j["best_isa"] = {{"isa", best}, {"device", bd}, {"phong_sleef", bp}, {"speedup", bd > 0 ? bp / bd : 0.0}};
  const double setup_rate = t["setup_batch"] > 0 ? 1e3 / t["setup_batch"] : 0.0;  // M spans/s
  const double core_rate = mean_span > 0 ? fmax_mhz / mean_span : 0.0;           // M spans/s
  j["setup_mspans_per_s"] = setup_rate;
  j["core_mspans_per_s_at_fmax"] = core_rate;
  j["host_cores_to_feed"] = setup_rate > 0 ? core_rate / setup_rate : 0.0;
  j["setup_over_core_rate"] = core_rate > 0 ? setup_rate / core_rate : 0.0;  // goal: >= 1.5
  j["samples"] = reps;
  // Sanity figures of this run's outputs (the tests check them properly:
  // tests/report/test_shade_spans.cpp): device against C cos^n(psi) from the same registers,
  // Phong against the per-pixel truth, both as max |difference| (C is at most 2).
  j["max_abs_device_vs_pow_cos"] = max_abs_diff(out_dev, out_pc, pixels);
  double worst_phong = 0.0;
  size_t at = 0;
  for (const Span& s : spans)
    for (int i = 0; i <= s.length(); ++i, ++at)
      worst_phong = std::max(worst_phong, std::abs(out_ps[at] - pixel_truth(scene, s, i)));
  j["max_abs_phong_sleef_vs_truth"] = worst_phong;
  return j;
}

json break_even(int max_len, size_t count, int reps, double min_time) {
  const device::Format f;
  static const host::DeviceShader shader(f);
  json rows = json::array();
  for (int l = 0; l <= max_len; ++l) {
    std::vector<ScanlineInput> in = host::random_spans_of_length(count, 20261203u + static_cast<uint64_t>(l), l);
    for (ScanlineInput& s : in) s.he = s.h1;  // directional light, orthographic camera
    // Material by material, as in the scenes: grouped by the device's bank k.
    std::stable_sort(in.begin(), in.end(), [](const ScanlineInput& a, const ScanlineInput& b) {
      return device_span_plan(static_cast<int>(a.n)).k < device_span_plan(static_cast<int>(b.n)).k;
    });
    host::SpanBatch batch;
    for (const ScanlineInput& s : in) batch.push_back(s);
    const host::PhongSpans ps = host::phong_spans(in);
    const double np = static_cast<double>(ps.pixels());
    host::RegisterBatch regs;
    std::vector<float> a(ps.pixels() + 8), b(ps.pixels() + 8);
    std::vector<Method> ms;
    ms.push_back({"device", [&] { host::setup_batch(batch, f, regs); shader.shade(regs, a.data()); }, np});
    ms.push_back({"phong_sleef", [&] { host::shade_phong(ps, b.data(), SimdPath::automatic); }, np});
    add_isa_methods(ms, &batch, &f, &regs, &shader, &ps, a.data(), b.data(), np);
    time_methods(ms, reps, min_time);
    json row = {{"l", l}, {"pixels_per_span", l + 1}, {"spans", count}};
    for (const Method& m : ms) row[m.name] = m.median();
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Time shading every span of each scene by the device method (setup included) and its competitors"};
  std::vector<std::string> scenes;
  std::string json_path, fpga_path = SPECULAR_FPGA_FIGURES;
  int reps = 5, max_len = 63, be_spans = 4096;
  double min_time = 0.02;
  bool no_break_even = false;
  app.add_option("scenes", scenes, "scene files (scenes/*.json)")->required()->check(CLI::ExistingFile);
  app.add_option("--json", json_path, "write the results as JSON to FILE");
  app.add_option("--reps", reps, "rounds per scene (the median is reported)")->check(CLI::Range(1, 1000));
  app.add_option("--min-time", min_time, "seconds of CPU time per sample")->check(CLI::Range(1e-6, 10.0));
  app.add_option("--max-len", max_len, "break-even sweep: l = 0..L")->check(CLI::Range(0, kMaxLen));
  app.add_option("--break-even-spans", be_spans, "break-even sweep: spans per length")->check(CLI::Range(1, 1 << 20));
  app.add_flag("--no-break-even", no_break_even, "skip the break-even sweep");
  app.add_option("--fpga-figures", fpga_path, "the make fpga figures (default: the repository's docs/fpga_figures.json)");
  if (auto code = parse_command_line(app, argc, argv, "scene_bench")) return *code;

  json out;
  try {
    std::string fmax_source;
    const double fmax = stream_fmax_mhz(fpga_path, fmax_source);
    out["fmax_mhz"] = fmax;
    out["fmax_source"] = fmax_source;
    out["simd"] = simd_description();
    out["best_isa"] = best_isa();
    char timer[160];
    std::snprintf(timer, sizeof timer, "CLOCK_THREAD_CPUTIME_ID, median of %d interleaved rounds of >= %g s", reps, min_time);
    out["timer"] = timer;
    out["scenes"] = json::array();
    for (const std::string& p : scenes) {
      const json j = bench_scene(p, reps, min_time, fmax);
      const json& t = j["ns_per_pixel"];
      const json& r = j["speedup_vs_phong_sleef"];
      std::printf("%s: %zu spans, %zu pixels, %.2f pixels per span\n", j["scene"].get<std::string>().c_str(),
                  j["spans"].get<size_t>(), j["pixels"].get<size_t>(), j["mean_span"].get<double>());
      const json& b = j["best_isa"];
      std::printf("  headline, both at %s: device %.3f, phong_sleef %.3f ns/pixel: %.2f x\n",
                  b["isa"].get<std::string>().c_str(), b["device"].get<double>(), b["phong_sleef"].get<double>(),
                  b["speedup"].get<double>());
      for (const char* m : {"device", "phong_sleef", "phong_scalar", "pow_cos"})
        std::printf("  %-13s %8.3f ns/pixel  %6.2f x phong_sleef\n", m, t[m].get<double>(), r[m].get<double>());
      for (const auto& [isa, m] : j["isa_matched"].items())
        std::printf("  %-6s throughout: device %.3f, phong_sleef %.3f ns/pixel: %.2f x\n", isa.c_str(),
                    m["device"].get<double>(), m["phong_sleef"].get<double>(), m["speedup"].get<double>());
      std::printf("  setup %.2f ns/span (%.1f M spans/s on one core), shading %.3f ns/pixel; the core at %.2f MHz takes "
                  "%.1f M spans/s: %.2f host cores to feed it (one core: %.2f x its rate)\n",
                  j["device_setup_ns_per_span"].get<double>(), j["setup_mspans_per_s"].get<double>(),
                  j["device_shade_ns_per_pixel"].get<double>(), fmax, j["core_mspans_per_s_at_fmax"].get<double>(),
                  j["host_cores_to_feed"].get<double>(), j["setup_over_core_rate"].get<double>());
      std::fflush(stdout);
      out["scenes"].push_back(j);
    }
    out["break_even"] = json::array();
    out["break_even_l"] = nullptr;
    if (!no_break_even) {
      out["break_even"] = break_even(max_len, static_cast<size_t>(be_spans), reps, min_time);
      // The first l where the device is at or below Phong: as defined (device, phong_sleef)
      // and at one instruction set.
      json lens = json::object();
      for (const auto& [key, dev, phong] : {std::tuple{"default", "device", "phong_sleef"},
                                            std::tuple{"avx2", "device_avx2", "phong_sleef"},
                                            std::tuple{"avx512", "device_avx512", "phong_sleef_avx512"}}) {
        if (!out["break_even"][0].contains(dev)) continue;
        lens[key] = nullptr;
        for (const json& r : out["break_even"])
          if (r[dev].get<double>() <= r[phong].get<double>()) {
            lens[key] = r["l"];
            break;
          }
      }
      out["break_even_l_isa"] = lens;
      out["break_even_l"] = lens["default"];
      std::printf("break-even (synthetic spans, constant H), the first l where the device is at or below Phong:");
      for (const auto& [key, v] : out["break_even_l_isa"].items()) {
        if (v.is_null())
          std::printf(" %s: none in 0..%d;", key.c_str(), max_len);
        else
          std::printf(" %s: l = %d (%d pixels per span);", key.c_str(), v.get<int>(), v.get<int>() + 1);
      }
      std::printf("\n");
      for (const json& r : out["break_even"]) {
        std::printf("  l = %2d: ns/pixel", r["l"].get<int>());
        for (const char* m : {"device", "phong_sleef", "device_avx2", "device_avx512", "phong_sleef_avx512"})
          if (r.contains(m)) std::printf(" %s %.3f", m, r[m].get<double>());
        std::printf("\n");
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "scene_bench: error: " << e.what() << "\n";
    return 2;
  }
  if (!json_path.empty()) {
    std::ofstream f(json_path);
    if (!f) {
      std::cerr << "scene_bench: error: cannot write " << json_path << "\n";
      return 2;
    }
    f << out.dump(1) << "\n";
  }
  return 0;
}
