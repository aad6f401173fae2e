// SPDX-License-Identifier: Apache-2.0
// report_data: the model-side measurements of the speed-against-error report as JSON.
//   report_data [--out FILE] [--n-step S] [--section NAME]...
// Sections (all by default):
//   evaluators  docs/metrics.md errors (max relative epicenter, max absolute lobe) of every
//               C++ evaluator of model/reference/evaluators.hpp for n = 1, 1+S, ... 1000 (and 1000)
//   curves      evaluator values against the angle for n = 5, 50, 500 (error-vs-angle plots)
//   albedo      albedo against n, both conventions: normalized blinn, f16, kutlog (exact
//               coef and the paper's fits)
//   hardware    device error of RTL configurations, measured with the golden fixed-point
//               model over scanlines for every n in 1..1000, plus the ROM sizes
//   hardcases   the docs/scanline_setup.md hard cases through scanline_setup, one object each
// Non-finite numbers are written as the strings "inf", "-inf", "nan" (JSON has no such
// numbers). Exit code 2 on bad arguments (nothing written).
#include "blend_rom.hpp"
#include "cli_parse.hpp"
#include "brdf.hpp"
#include "coefficients.hpp"
#include "device_model.hpp"
#include "device_error.hpp"
#include "evaluators.hpp"
#include "metrics.hpp"
#include "rom_image.hpp"
#include "scanline_setup.hpp"
#include "span_shade.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <vector>

using json = nlohmann::json;
using namespace specular;

namespace {

constexpr double kHalfPi = 1.57079632679489661923;

json num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

std::vector<int> n_grid(int step) {
  std::vector<int> ns;
  for (int n = 1; n <= kMaxN; n += step) ns.push_back(n);
  if (ns.back() != kMaxN) ns.push_back(kMaxN);
  return ns;
}

// One evaluator as a function of the angle x for exponent n (cosine-input ones get cos x).
struct EvalDef {
  std::string name, input;
  std::function<ShapeFn(int)> make;
};

// phong_span at one pixel whose normal makes angle x with H.
double phong_at(double x, int n, SimdPath path) {
  const Vec3f N{float(std::sin(x)), 0.0f, float(std::cos(x))}, H{0.0f, 0.0f, 1.0f};
  float v;
  phong_span(N, N, H, float(n), 0, 1.0f, &v, path);
  return v;
}

std::vector<EvalDef> evaluator_defs() {
  auto cosine = [](auto eval) { return ShapeFn([eval](double x) { return eval(std::cos(x)); }); };
  return {
      {"pow", "cosine", [=](int n) { return cosine(PowEval{double(n)}); }},
      {"exp2poly", "cosine", [=](int n) { return cosine(Exp2PolyEval{double(n)}); }},
      {"lut256", "cosine", [=](int n) { return cosine(LutEval(n)); }},
      {"schlick", "cosine", [=](int n) { return cosine(SchlickEval{double(n)}); }},
      {"schlick_mod", "cosine", [=](int n) { return cosine(SchlickModEval{double(n)}); }},
      {"lyon16", "cosine", [=](int n) { return cosine(LyonEval(n, 4)); }},
      {"prototype", "angle", [](int n) { return ShapeFn(prototype_eval(n)); }},
      {"patent", "angle", [](int n) { return ShapeFn(patent_eval(n, CoefSpec{CoefPolicy::maclaurin})); }},
      {"patent_minimax", "angle", [](int n) { return ShapeFn(patent_eval(n, CoefSpec{CoefPolicy::minimax})); }},
      // Whole-span evaluators of model/reference/span_shade.hpp, one pixel at a time.
      {"pow_cos", "angle", [](int n) { return ShapeFn([n](double x) { double v; pow_cos_span(n, x, 0.0, 0, 1.0, &v); return v; }); }},
      {"device_simd", "angle", [](int n) {
         const DeviceSpanPlan p = device_span_plan(n);
         return ShapeFn([p](double x) { float v; device_span(p, x, 0.0, 0, 1.0f, &v); return double(v); });
       }},
      {"phong_scalar", "normal", [](int n) { return ShapeFn([n](double x) { return phong_at(x, n, SimdPath::scalar); }); }},
      {"phong_sleef", "normal", [](int n) { return ShapeFn([n](double x) { return phong_at(x, n, SimdPath::automatic); }); }},
  };
}

json section_evaluators(const std::vector<int>& ns) {
  json out = json::array();
  for (const EvalDef& d : evaluator_defs()) {
    json rel = json::array(), ab = json::array();
    for (int n : ns) {
      const ShapeError e = shape_error(d.make(n), n);
      rel.push_back(num(e.max_rel_epicenter));
      ab.push_back(num(e.max_abs_lobe));
    }
    out.push_back({{"name", d.name}, {"input", d.input}, {"n", ns}, {"max_rel_epicenter", rel}, {"max_abs_lobe", ab}});
  }
  return out;
}

json section_curves() {
  json out = json::array();
  for (int n : {5, 50, 500}) {
    const double end = std::min(kHalfPi, 4.0 / std::sqrt(double(n)));
    std::vector<double> xs;
    for (int i = 0; i <= 400; ++i) xs.push_back(end * i / 400.0);
    json series = json::object();
    for (const EvalDef& d : evaluator_defs()) {
      const ShapeFn f = d.make(n);
      json ys = json::array();
      for (double x : xs) ys.push_back(num(f(x)));
      series[d.name] = ys;
    }
    json ref = json::array();
    for (double x : xs) ref.push_back(std::pow(std::cos(x), n));
    out.push_back({{"n", n}, {"x", xs}, {"epicenter_end", epicenter_end(n)}, {"reference", ref}, {"series", series}});
  }
  return out;
}

json section_albedo() {
  // 1..10, then ~15 % steps, plus the round values the report's table quotes.
  std::set<int> grid{20, 50, 100, 200, 500, kMaxN};
  for (int n = 1; n <= kMaxN; n = n < 10 ? n + 1 : int(std::ceil(n * 1.15))) grid.insert(n);
  const std::vector<int> ns(grid.begin(), grid.end());
  struct Series {
    std::string name;
    std::function<ShapeFn(int)> f;
    int min_n = 1;
  };
  // kutlog with k = 2 at Q = 0.3 (first fit range) and Q = 0.7 (second); the fits hold for
  // n in [k+1, 1000] per the paper.
  constexpr int kK = 2;
  std::vector<Series> all{
      {"blinn (n+8)/(8 pi)", [](int n) { return ShapeFn([n](double x) { return blinn_phong_norm(n) * blinn(x, n); }); }},
      {"lyon16 (n+8)/(8 pi)", [](int n) { return ShapeFn([n](double x) { return blinn_phong_norm(n) * lyon(std::cos(x), n, 16); }); }},
      {"f16 (n+6)/24.55", [](int n) { return ShapeFn([n](double x) { return f16(std::cos(x), n); }); }},
  };
  for (double Q : {0.3, 0.7}) {
    char qs[16];
    std::snprintf(qs, sizeof qs, "%.1f", Q);
    all.push_back({std::string("kutlog k=2 Q=") + qs + " exact coef", [Q](int n) {
                     const double c = kutlog_coef_exact(n, kK, Q);
                     return ShapeFn([=](double x) { return c * kutlog_shape(x, n, kK, Q); });
                   }, kK + 1});
    all.push_back({std::string("kutlog k=2 Q=") + qs + " fit coef", [Q](int n) {
                     const double c = kutlog_coef_fit(n, kK, Q);
                     return ShapeFn([=](double x) { return c * kutlog_shape(x, n, kK, Q); });
                   }, kK + 1});
  }
  json series = json::array();
  for (const Series& s : all) {
    json nn = json::array(), ph = json::array(), bl = json::array();
    for (int n : ns) {
      if (n < s.min_n) continue;
      const ShapeFn f = s.f(n);
      nn.push_back(n);
      ph.push_back(num(albedo(f, Convention::phong, n)));
      bl.push_back(num(albedo(f, Convention::blinn, n)));
    }
    series.push_back({{"name", s.name}, {"n", nn}, {"phong", ph}, {"blinn", bl}});
  }
  return series;
}

// The hardware configurations are build_configs() (rom_image.hpp): the ones sim_regression
// verilates and checks bit-exactly, so every figure here is one the RTL produces. Their
// decoder tables come from derive_bank_max_n (decoder_table.hpp); tests/report checks the
// patent's table 1 | 2 | 3..6 | 7..1000 for {1, 2, 4, 16}.
json section_hardware(const std::vector<int>& ns) {
  json out = json::array();
  for (const BuildConfig& c : build_configs()) {
    const device::Format& f = c.f;
    const auto t0 = std::chrono::steady_clock::now();
    // A blend build's ROM 9 comes from its fits (blend_rom.hpp), the others' from their policy.
    const device::DeviceModel dm = f.blend ? blend_device_model(f, blend_table_for(f))
                                           : device::DeviceModel(f, coef_rom_image(f, parse_coef_spec(c.policy)),
                                                                 cos_rom_image(f));
    json rel = json::array(), ab = json::array(), rel_lsb = json::array();
    for (int n : ns) {
      const DeviceError e = device_error(dm, n);
      rel.push_back(num(e.max_rel_epicenter));
      ab.push_back(num(e.max_abs_lobe));
      rel_lsb.push_back(num(e.max_rel_epicenter_lsb));
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.push_back({{"name", c.name},
                   {"cos_interp", f.cos_interp},
                   {"cos_addr_bits", f.cos_addr_bits},
                   {"cos_data_bits", f.cos_data_bits},
                   {"cos_word_bits", f.cos_word_bits()},
                   {"coef_bits", f.coef_bits},
                   {"coef_frac", f.coef_frac},
                   {"psi_mul_frac", f.psi_mul_frac},
                   {"cos_delta_bits", f.cos_delta_bits},
                   {"cos_frac_bits", f.cos_frac_bits},
                   {"policy", c.policy},
                   {"banks", f.banks},
                   {"bank_max_n", f.bank_max_n},
                   {"coef_rom", c.coef_hex()},
                   {"cos_rom", c.cos_hex()},
                   {"blend", f.blend},
                   {"coef_rom_bits", int64_t(f.coef_rom_depth()) * f.coef_word_bits()},
                   {"cos_rom_bits", int64_t(f.cos_rom_depth()) * f.cos_word_bits()},
                   {"n", ns},
                   {"max_rel_epicenter", rel},
                   {"max_rel_epicenter_lsb", rel_lsb},
                   {"max_abs_lobe", ab},
                   {"seconds", secs}});
  }
  return out;
}

json section_hardcases() {
  using glm::dvec3;
  const dvec3 z{0, 0, 1};
  auto unit = [](dvec3 v) { return v / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); };
  auto tilt = [&](double ang) { return dvec3{std::sin(ang), 0, std::cos(ang)}; };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    std::string name;
    ScanlineInput in;
  };
  auto base = [&](double n, int l) {
    ScanlineInput in;
    in.n1 = tilt(-0.2);
    in.n2 = tilt(0.2);
    in.h1 = tilt(0.05);
    in.he = in.h1;
    in.n = n;
    in.l = l;
    return in;
  };
  std::vector<Case> cases;
  {
    ScanlineInput in = base(50, 100);
    in.n2 = in.n1;
    cases.push_back({"N1 = N2 (gamma = 0)", in});
  }
  for (double eps : {1e-6, 1e-9, 1e-12}) {
    ScanlineInput in = base(50, 100);
    in.n2 = tilt(-0.2 + eps);
    char b[64];
    std::snprintf(b, sizeof b, "gamma tiny (N2 = N1 turned by %.0e rad)", eps);
    cases.push_back({b, in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.h1 = in.he = unit(dvec3{1, 0, -0.1});
    cases.push_back({"cos t1 <= 0 (H1 below the surface)", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.n1 = z;
    in.n2 = -z;
    cases.push_back({"N1 = -N2 (1 + c = 0)", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.h1 = in.he = dvec3{0, 0, 0};
    cases.push_back({"L = -V (|L + V| = 0, zero H)", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.n1 = 3.0 * in.n1;
    in.h1 = in.he = 0.5 * in.h1;
    cases.push_back({"non-unit N1 (x3) and H (x0.5)", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.n2 = dvec3{0, 0, 0};
    cases.push_back({"zero-length N2", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.n1 = dvec3{nan, 0, 1};
    cases.push_back({"NaN in N1", in});
  }
  cases.push_back({"l = 0 (one pixel)", base(50, 0)});
  cases.push_back({"l = " + std::to_string(kMaxLen) + " (counter maximum)", base(50, kMaxLen)});
  for (const int edge : patent_bank_edges()) {
    const double n = edge;
    char b[64];
    std::snprintf(b, sizeof b, "n = %g", n);
    cases.push_back({b, base(n, 100)});
  }
  {
    ScanlineInput in = base(50, 100);
    in.h1 = in.he = z;  // normals sweep -0.2..0.2 rad through H: psi crosses 0 mid-span
    cases.push_back({"psi crosses 0 inside the span (peak)", in});
  }
  {
    ScanlineInput in = base(50, 100);
    in.n1 = tilt(-1.4);
    in.n2 = tilt(1.4);
    in.h1 = in.he = z;
    cases.push_back({"psi beyond +-pi/2 at both ends", in});
  }

  const device::Format f;
  const device::DeviceModel dm(f, coef_rom_image(f, CoefSpec{CoefPolicy::minimax}), cos_rom_image(f));
  json out = json::array();
  for (const Case& c : cases) {
    const ScanlineSetup s = scanline_setup(c.in);
    const bool finite = std::isfinite(s.A) && std::isfinite(s.lambda) && std::isfinite(s.gamma) &&
                        std::isfinite(s.C) && std::isfinite(s.psi0) && std::isfinite(s.dpsi);
    // The golden model on the resulting registers against C cos^n(psi_i) at the device's
    // quantized angles: what the device would output for this line.
    const int l = std::clamp(c.in.l, 0, kMaxLen);
    const device::RegisterLoad load = device::load_registers(s, c.in.n, l, f);
    const device::Registers& r = load.reg;
    const bool c_sat = load.c_saturated;
    const std::vector<uint32_t> px = dm.line(r);
    double peak = 0.0, max_err = 0.0;
    const double cq = device::c_value(r.c, f), p0 = device::angle_value(r.psi0, f), dp = device::angle_value(r.dpsi, f);
    for (int i = 0; i <= l; ++i) {
      const double got = device::c_value(px[i], f);
      const double psi = p0 + i * dp;
      const double ref = std::abs(psi) < kHalfPi ? cq * std::pow(std::cos(psi), c.in.n) : 0.0;
      peak = std::max(peak, got);
      max_err = std::max(max_err, std::abs(got - ref));
    }
    out.push_back({{"case", c.name},
                   {"n", c.in.n},
                   {"l", c.in.l},
                   {"status", to_string(s.status)},
                   {"A", num(s.A)},
                   {"lambda", num(s.lambda)},
                   {"gamma", num(s.gamma)},
                   {"C", num(s.C)},
                   {"psi0", num(s.psi0)},
                   {"dpsi", num(s.dpsi)},
                   {"finite", finite},
                   {"c_saturated", c_sat},
                   {"angle_saturated", load.angle_saturated},
                   {"device_peak", peak},
                   {"device_max_abs_error", max_err},
                   {"note", s.note}});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_path;
  int n_step = 1;
  std::vector<std::string> sections;
  const std::set<std::string> known{"evaluators", "curves", "albedo", "hardware", "hardcases"};
  CLI::App app{"Model-side measurements of the speed-against-error report, as JSON"};
  app.add_option("--out", out_path, "output file (default: stdout); written whole or not at all");
  app.add_option("--n-step", n_step, "sample n = 1, 1+S, ..., 1000 (S in 1..999)")->capture_default_str();
  app.add_option("--section", sections, "evaluators, curves, albedo, hardware, hardcases (repeatable; default all)");
  if (const auto exit_code = specular::parse_command_line(app, argc, argv, "report_data")) return *exit_code;
  if (n_step < 1 || n_step > 999) {
    std::cerr << "report_data: --n-step must be in 1..999 (got " << n_step << ")\n";
    return 2;
  }
  for (const auto& s : sections) {
    if (!known.count(s)) {
      std::cerr << "report_data: --section '" << s
                << "' is not one of evaluators, curves, albedo, hardware, hardcases\n";
      return 2;
    }
  }
  if (sections.empty()) sections.assign(known.begin(), known.end());
  const std::set<std::string> want(sections.begin(), sections.end());

  const std::vector<int> ns = n_grid(n_step);
  json doc;
  doc["n_step"] = n_step;
  auto timed = [&](const std::string& key, auto fn) {
    if (!want.count(key)) return;
    const auto t0 = std::chrono::steady_clock::now();
    doc[key] = fn();
    doc["seconds"][key] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  try {
    timed("evaluators", [&] { return section_evaluators(ns); });
    timed("curves", [&] { return section_curves(); });
    timed("albedo", [&] { return section_albedo(); });
    timed("hardware", [&] { return section_hardware(ns); });
    timed("hardcases", [&] { return section_hardcases(); });
  } catch (const std::exception& e) {
    std::cerr << "report_data: " << e.what() << "\n";
    return 1;
  }

  const std::string text = doc.dump(1) + "\n";
  if (out_path.empty()) {
    std::cout << text;
    return 0;
  }
  const std::string tmp = out_path + ".tmp";
  {
    std::ofstream os(tmp);
    os << text;
    if (!os) {
      std::cerr << "report_data: cannot write " << tmp << "\n";
      return 1;
    }
  }
  std::filesystem::rename(tmp, out_path);
  return 0;
}
