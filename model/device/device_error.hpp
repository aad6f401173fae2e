// SPDX-License-Identifier: Apache-2.0
// The device error of a build configuration, measured on its golden model: the error metrics
// of docs/metrics.md at the pixels of scanlines of 2048 pixels (the report's hardware rows and
// the design of decoder 10 use it).
#pragma once

#include "device_model.hpp"

#include <cstdint>

namespace specular {

// The golden fixed-point model along one scanline: psi_i = i * dpsi (i = 0..l) and the
// device output I_i / C with C = 1. Used for timing (per-pixel cost of DeviceModel::line)
// and for the device error sweep.
struct DeviceLine {
  device::Registers regs;
  double dpsi = 0.0;  // exact value of the quantized increment (radians)
  double c = 1.0;     // exact value of the quantized C
};
// The line from psi = 0 to about `end` (radians) with l + 1 pixels, C = 1, exponent n.
DeviceLine make_device_line(const device::Format& f, int n, double end, int l);

// Device error of one configuration at exponent n, docs/metrics.md metrics measured at the
// pixels of three scanlines of 2048 pixels (l = 2047): [0, x_e(n)] for the relative
// epicenter error, [0, min(pi/2, 12/sqrt(n))] and [0, pi/2] for the absolute lobe error.
// The reference is C cos^n(psi_i) at the exact (quantized) pixel angle, so the figure is
// the device error alone, not the host's quantization of psi0/dpsi.
// max_rel_epicenter_lsb is the goal metric of the hardware builds: (|err| - 1 output LSB) /
// ref over the epicenter, n = 1 over all of [0, pi/2] wherever ref >= 4 output LSBs.
struct DeviceError {
  double max_rel_epicenter = 0.0;
  double max_abs_lobe = 0.0;
  double max_rel_epicenter_lsb = 0.0;
  // What a viewer sees (docs/display_exact.md#search): the largest difference, in codes, between
  // the 8-bit sRGB encodings (IEC 61966-2-1, round to nearest) of the output and of the
  // reference, over the same pixels as max_abs_lobe (C = 1: a full-scale highlight).
  int max_srgb8_codes = 0;
};
// The 8-bit sRGB code of a linear intensity (clamped to [0, 1]).
int srgb8_code(double linear);
DeviceError device_error(const device::DeviceModel& dm, int n);

// The absolute error of exponent n on a dense sweep (the display budgets are absolute and every
// pixel counts): C = 1, every `step_codes`-th angle code from psi = 0 to the end of the lobe,
// min(pi/2, sqrt(40 / n)) (past it cos^n < e^-20), lines of the longest l back to back; the
// reference C cos^n(psi) at the exact pixel angle. device_error's three lines miss the worst
// pixel by a few per cent (docs/display_exact.md#search).
struct DenseError {
  double max_abs = 0.0;  // fraction of C
  double psi = 0.0;      // where
  long pixels = 0;
};
DenseError dense_abs_error(const device::DeviceModel& dm, int n, int64_t step_codes);

}  // namespace specular
