// Scene stage of the regression: every scenes/*.json rasterized into spans (model/scene/raster),
// each span's registers (span_registers) run through the verilated device, every pixel
// checked by the same Checker as the regression lines ((a)-(d)), and five images per scene:
//   <scene>_phong.png         per-pixel Phong truth (pixel_truth)
//   <scene>_float.png         spherical-interpolation float model (float_model_evaluator)
//   <scene>_rtl.png           the RTL output
//   <scene>_device_error.png  heatmap RTL - C cos^n(psi_i) from the loaded registers (check (c))
//   <scene>_interp_error.png  heatmap float model - Phong truth
#pragma once

#include "checks.hpp"
#include "harness.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "scene.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace specular::sim {

struct LoadedScene {
  Scene scene;
  Raster raster;
  double raster_seconds = 0.0;
};

// Every DIR/*.json in file-name order, loaded and rasterized. Throws SceneError (message
// names the file) for a bad scene, std::runtime_error when DIR is not a directory.
std::vector<LoadedScene> load_scenes(const std::string& dir);

struct SceneStats {
  std::string name, policy;
  int width = 0, height = 0;
  size_t triangles = 0, spans = 0, covered_pixels = 0, max_l = 0;
  size_t c_saturated_spans = 0;  // setup's C >= 2 clamped into reg 1: reported, not a failure
  PolicyStats checks;            // (a)-(d) over the scene's spans, same budgets as the lines
  Extreme dev_abs;               // max |RTL - C cos^n(psi_i)| over span pixels, intensity units
  ImageErrorStats device_image;  // the device-error heatmap (lights summed)
  ImageErrorStats interp_image;  // float model - Phong truth
  ImageErrorStats register_image;  // float model - C cos^n(psi_i) of the loaded registers: C saturation, rounding
  double peak_phong = 0.0;
  double raster_seconds = 0.0, image_seconds = 0.0;  // rasterization; PNG encoding and writing
  std::vector<std::string> images;  // files written (empty when this policy wrote none)

  bool ok() const {
    return checks.lines > 0 && checks.mismatches == 0 && checks.protocol_errors == 0 &&
           checks.quant_violations == 0 && checks.rel_violations == 0 && checks.abs_violations == 0 &&
           checks.latency.size() == 1 && checks.latency.begin()->first == checks.expected_latency;
  }
  nlohmann::json to_json() const;
};

// Images, error statistics and timing of the non-RTL part (phong and float images count as
// reference time). Writes the PNGs when images_dir is not empty (whole files: temp + rename).
void finish_scene(SceneStats& s, const LoadedScene& ls, const Image& rtl, const Image& reference,
                  const std::string& images_dir);

template <class V>
SceneStats run_scene(Harness<V>& h, const Checker& checker, const std::string& policy, const LoadedScene& ls,
                     const std::string& images_dir, std::mt19937_64& rng) {
  using Clock = std::chrono::steady_clock;
  const auto& f = h.model().format();
  SceneStats s;
  s.name = ls.scene.name;
  s.policy = policy;
  s.checks.policy = policy + " scene " + s.name;
  s.raster_seconds = ls.raster_seconds;
  const auto t0 = Clock::now();
  Image rtl(ls.raster.width, ls.raster.height), reference(ls.raster.width, ls.raster.height);
  const double lsb = std::ldexp(1.0, -f.c_frac);
  size_t idx = 0;
  for (const Span& sp : ls.raster.spans) {
    Scanline sl;
    sl.reg = span_registers(sp, f, &sl.c_saturated);
    sl.kind = "scene:" + s.name;
    s.c_saturated_spans += sl.c_saturated;
    const WriteMode mode = ++idx % 2 ? WriteMode::before_start : WriteMode::with_start;
    const auto s0 = Clock::now();
    const LineRun run = h.run_line(sl.reg, mode, 0.0, 0, rng);
    s.checks.sim_seconds += std::chrono::duration<double>(Clock::now() - s0).count();
    checker.check_line(sl, run, false, s.checks);
    const std::vector<double>& ref = checker.last_reference();
    for (size_t i = 0; i < ref.size(); ++i) {
      const int x = sp.x_start + static_cast<int>(i);
      const double out = run.pixels[i] * lsb;
      rtl.at(x, sp.y) += out;
      reference.at(x, sp.y) += ref[i];
      rtl.covered[static_cast<size_t>(sp.y) * rtl.width + x] = 1;
      reference.covered[static_cast<size_t>(sp.y) * reference.width + x] = 1;
      const double e = std::fabs(out - ref[i]);
      if (e > s.dev_abs.value)
        s.dev_abs = {e, sl.reg.n, device::angle_value(sl.reg.psi0 + static_cast<int64_t>(i) * sl.reg.dpsi, f),
                     device::c_value(sl.reg.c, f), sl.reg.len, static_cast<int>(i), sl.kind};
    }
  }
  s.checks.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  finish_scene(s, ls, rtl, reference, images_dir);
  return s;
}

// Scene rows of the summary (one per scene and policy).
void print_scene_table(const std::vector<SceneStats>& all);

}  // namespace specular::sim
