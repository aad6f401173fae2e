// SPDX-License-Identifier: Apache-2.0
// Scanlines for the regression: register contents produced by the model's scanline setup
// (docs/scanline_setup.md) from geometry, plus raw register patterns the setup never produces.
#pragma once

#include "device_model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular::sim {

struct Scanline {
  device::Registers reg;
  std::string kind;         // "sweep-wide", "sweep-epicenter", "sweep-l", "hard:<case>", "raw:<case>", "random"
  bool c_saturated = false; // the setup's C did not fit register 1 and was clamped
};

// Every n in 1..max_n over spans crossing 0 and past +-pi/2, l in {0,1,2,3,2047}, C at 0,
// mid and full scale, the hard cases of docs/scanline_setup.md, and raw register edge patterns.
std::vector<Scanline> deterministic_scanlines(const device::Format& f);

// `count` random scanlines from random geometry (fixed by `seed`): most lines short, a few
// at the counter maximum.
std::vector<Scanline> random_scanlines(const device::Format& f, uint64_t seed, int count);

}  // namespace specular::sim
