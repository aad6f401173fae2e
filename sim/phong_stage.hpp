// SPDX-License-Identifier: Apache-2.0
// Phong stage of the regression (docs/phong_hw.md#verification): every scene's spans, the
// raster's setup inputs quantized to the geometry span interface (device::quantize_geo),
// streamed back to back through the verilated phong_stream in both forms at the device's
// budget (n1000, the textbook form, and cross_n1000, the cancellation-free form of
// docs/phong_hw.md#the-cancellation-free-form), every pixel, tag and last flag checked
// bit-exactly against its golden model
// (device::PhongModel), and its error measured against per-pixel Phong in double
// (device::phong_exact; phong_truth beside it) with the device's budget: |err| <= 0.10 % of
// the pixel + 1 LSB where psi <= x_e(n) (n = 1: ref >= 4 LSB), |err| <= 0.01 C + 1 LSB
// everywhere (docs/metrics.md).
#pragma once

#include "scene_stage.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular::sim {

struct PhongSceneStats {
  std::string name;
  std::string config;  // n1000 or cross_n1000 (roms/phong/phong_configs.cmake)
  uint64_t spans = 0, pixels = 0, cycles = 0;
  uint64_t mismatches = 0;       // RTL against the golden model (intensity, last, tag)
  uint64_t epicenter_pixels = 0;
  uint64_t rel_violations = 0, abs_violations = 0;
  double rel_lsb = 0.0, abs_lsb = 0.0;              // against phong_exact
  double rel_lsb_truth = 0.0, abs_lsb_truth = 0.0;  // against phong_truth
  double seconds = 0.0;                             // wall time of the scene (RTL, golden, references)
  std::vector<std::string> failures;
  bool ok() const { return mismatches == 0 && rel_violations == 0 && abs_violations == 0 && pixels > 0; }
};

// Runs every scene through phong_stream in both forms (px_ready_i high, spans offered back to
// back): the textbook form's stats, then the cross form's.
std::vector<PhongSceneStats> run_phong_stage(const std::vector<LoadedScene>& scenes);
void print_phong_table(const std::vector<PhongSceneStats>& stats);

}  // namespace specular::sim
