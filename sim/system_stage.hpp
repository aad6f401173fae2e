// SPDX-License-Identifier: Apache-2.0
// System stage of the regression: rtl/specular_system (the setup in hardware, then
// specular_stream; docs/setup_hw.md#the-system) from geometry spans to pixels.
//   scenes   every scene's spans (scene_stage.hpp's rasterization) quantized to the geometry
//            span interface (device::quantize_geo), back to back with px_ready_i high: every
//            pixel bit-exact against the golden models (host::fixed::setup_fixed, then
//            DeviceModel::stream); clocks per pixel; the setup error (the setup's registers
//            against the reference of its contract on the same inputs, host::check_contract:
//            0.01 % + 1 LSB, and the decisions outside the guard bands) and the end-to-end error
//            (the RTL's pixels against C cos^n(psi_i) of that reference: the device budget + 1 LSB)
//   l0       one-pixel spans back to back: one pixel per clock
//   random   random geometry spans with every hard case (tests/model/geo_cases.hpp) under
//            random gaps, random px_ready_i and random resets, bit-exact
#pragma once

#include "device_model.hpp"
#include "rom_image.hpp"
#include "scene_stage.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular::sim {

struct SystemRunStats {
  std::string name;
  uint64_t spans = 0, pixels = 0;
  uint64_t mismatches = 0;      // intensity, last or tag differs from the golden models
  uint64_t protocol_errors = 0; // pixel without a span, hold rule, spans not drained
  uint64_t resets = 0;
  uint64_t cycles_fill = 0;     // first accept .. last pixel (the setup's and the stream's fill included)
  uint64_t cycles_steady = 0;   // first pixel .. last pixel
  // Setup error (fixed-point registers against the scalar double setup's).
  uint64_t status_mismatches = 0, setup_violations = 0;
  double setup_worst = 0.0, setup_rel = 0.0, setup_lsb = 0.0;
  // End to end (the RTL's pixels against C cos^n(psi_i) of the scalar double setup).
  uint64_t e2e_violations = 0, e2e_pixels = 0, c_saturated_spans = 0;
  double e2e_rel = 0.0;         // max relative error in the epicenter where the reference >= 2^-10
  double e2e_lsb = 0.0;         // max absolute error in output LSB
  double e2e_worst = 0.0;       // max error / allowance (<= 1 passes)
  std::vector<std::string> first_errors;
  double px_per_clock_fill() const { return cycles_fill ? double(pixels) / double(cycles_fill) : 0.0; }
  double px_per_clock_steady() const { return cycles_steady ? double(pixels) / double(cycles_steady) : 0.0; }
  bool ok() const {
    return pixels > 0 && mismatches == 0 && protocol_errors == 0 && status_mismatches == 0 && setup_violations == 0 &&
           e2e_violations == 0;
  }
};

struct SystemStats {
  int setup_ii = 1;                  // specular_system's SetupII
  std::vector<SystemRunStats> runs;  // scenes, then "l0", then "random"
  double seconds = 0.0;
  bool ok() const;
};

// `bc`: the default build configuration (specular_system has its parameter defaults).
// random_spans: random geometry spans of the random run (0: none). setup_ii: specular_system's
// SetupII (docs/setup_hw.md#the-folded-setup); 1 and 16 are always built, 8, 32 and 64 with the
// CMake option SPECULAR_SYSTEM_SETUP_II (system_setup_ii_built). Throws std::invalid_argument
// for a SetupII that is not built.
bool system_setup_ii_built(int setup_ii);
SystemStats run_system_stage(const std::vector<LoadedScene>& scenes, const BuildConfig& bc, uint64_t seed,
                             uint64_t random_spans, int setup_ii = 1);
void print_system_summary(const SystemStats& s);

}  // namespace specular::sim
