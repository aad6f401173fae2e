// SPDX-License-Identifier: Apache-2.0
// Per-pixel checks of the regression:
//   (a) bit-exact against the golden model,
//   (b) against C cos^k(a psi) in double with the policy's exact a (the quantization error,
//       in output LSBs; bounded by a first-order error budget of the formats, see checks.cpp),
//   (c) against C cos^n(psi) in double (the device error): relative in the epicenter
//       |psi| <= x_e(n), absolute over the lobe |psi| <= pi/2; budget + 1 output LSB,
//   (d) the protocol (the harness reports violations in LineRun::protocol_error).
// psi and C are the exact values of the quantized registers: the references take the
// register codes as the ports carry them and psi_i = psi0 + i dpsi by exact integer
// arithmetic (docs/device.md#fixed-point-contract), and use neither the golden model's
// accumulator nor its register latch nor its decoder; only (a) compares with the golden
// model. The line stages call
// check_line; the scene stage (scene_stage.hpp) calls references() and compare() per span,
// the first ahead of the RTL run (it needs only the registers), the second on the pixels the
// stream delivered.
#pragma once

#include "coefficients.hpp"
#include "device_model.hpp"
#include "harness.hpp"
#include "scanlines.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace specular::sim {

struct Budget {
  double rel_epicenter = 0.0;  // fraction of C cos^n(psi)
  double abs_lobe = 0.0;       // fraction of C
  // n = 1: the relative budget is enforced where the reference is at least this many output
  // LSBs (the interpolated ROM 12 bounds the relative error next to the zero of cos);
  // 0: n = 1 is only reported (a direct table cannot meet a relative budget there).
  double n1_min_ref_lsb = 0.0;
};

// Where an extreme value was seen.
struct Extreme {
  double value = 0.0;
  uint32_t n = 0;
  double psi = 0.0;
  double c = 0.0;
  uint32_t len = 0;
  int pixel = 0;
  std::string kind;
};

struct PolicyStats {
  std::string policy;
  Budget budget;
  uint64_t lines = 0, pixels = 0;
  uint64_t det_lines = 0, det_pixels = 0, rnd_lines = 0, rnd_pixels = 0;
  uint64_t mismatches = 0, protocol_errors = 0;
  uint64_t quant_violations = 0, rel_violations = 0, abs_violations = 0;
  uint64_t epicenter_pixels = 0, lobe_pixels = 0, c_saturated_lines = 0;
  Extreme quant_lsb;        // (b) max |I - C cos^k(a psi)| in output LSBs
  Extreme quant_excess;     // (b) max |err| / bound (must stay <= 1)
  Extreme rel_raw;          // (c) max |err| / ref in the epicenter, no allowance
  Extreme rel_raw_big;      // same, only where ref >= 0.5 (large signals)
  Extreme rel_allow;        // (c) max (|err| - 1 LSB) / ref in the epicenter
  Extreme abs_raw;          // (c) max |err| / C over the lobe
  Extreme abs_allow;        // (c) max (|err| - 1 LSB) / C over the lobe
  Extreme abs_outside;      // max (|err| - 1 LSB) / C where |psi| > pi/2 (reference 0)
  std::map<uint32_t, uint64_t> rel_violations_by_n;
  // n = 1: the epicenter [0, pi/2] ends at the zero of cos, where the relative error of a
  // direct table is unbounded (docs/metrics.md#maximum-relative-error-in-the-epicenter);
  // reported here, and part of ok() (rel_violations) only where the reference is at least
  // Budget::n1_min_ref_lsb output LSBs.
  Extreme rel_allow_n1;
  uint64_t n1_rel_over_budget = 0;
  double n1_budget_holds_below = 1e9;  // smallest |psi| at which n = 1 exceeds the relative budget
  std::map<int, uint64_t> latency;  // measured latency -> lines
  int expected_latency = -1;        // the documented one (specular_unit's Latency)
  uint64_t cycles = 0;      // from each start to the cycle the next start is accepted
  uint64_t long_line_cycles = 0, long_line_pixels = 0;  // lines with l = max (steady state)
  double seconds = 0.0;     // wall time of the simulation + checks
  double sim_seconds = 0.0; // wall time inside the Verilator harness only (the RTL: eval/tick)
  double golden_seconds = 0.0;     // wall time in the golden model (DeviceModel::trace)
  double reference_seconds = 0.0;  // wall time in the double references of (b) and (c)
  std::vector<std::string> failures;  // first few, human readable
  bool ok() const {
    return lines > 0 && mismatches == 0 && protocol_errors == 0 && quant_violations == 0 && rel_violations == 0 &&
           abs_violations == 0 && latency.size() == 1 && latency.begin()->first == expected_latency;
  }
  nlohmann::json to_json() const;
};

class Checker {
 public:
  // spec: the configuration's ROM 9 policy; the checker takes the exact a(n) from it, for
  // the k its own decoder 10 (from the format's table) gives n. A blend format (Format::blend)
  // has no policy: (b) is then the blend (1 - t) cos^k1(a1 |psi|) + t cos^k2(a2 |psi|) of the
  // values its ROM 9 words stand for (a1, a2, t = w / 2^W), spec unused.
  Checker(const device::DeviceModel& model, const CoefSpec& spec, Budget budget);
  // Checks every pixel of `run` against the three references and folds the result into `st`.
  // The golden model and the double references are computed in two timed passes before the
  // comparison (st.golden_seconds, st.reference_seconds).
  void check_line(const Scanline& sl, const LineRun& run, bool random, PolicyStats& st) const;

  // Of the last check_line: the (c) reference C cos^n(psi_i) of each checked pixel (0 past
  // pi/2 and for invalid n), from the loaded registers.
  const std::vector<double>& last_reference() const { return ref_c_; }

  // The double references of npix pixels of the registers r as written (each field is cut to
  // its port width here): psi_i = psi0 + i dpsi exactly, (b) C cos^k(a |psi_i|) and (c)
  // C cos^n(psi_i). Const and allocation-free, so it may run on another thread than the RTL.
  void references(const device::Registers& r, size_t npix, double* psi, double* ref_b, double* ref_c) const;
  // (a)-(c) for npix pixels of the registers r as written: `got` from the RTL, `golden` from the
  // golden model, the references from references(). Counts pixels, not lines.
  void compare(const device::Registers& r, const std::string& kind, size_t npix, const uint32_t* got,
               const uint32_t* golden, const double* psi, const double* ref_b, const double* ref_c,
               PolicyStats& st) const;

 private:
  const device::DeviceModel& model_;
  std::vector<double> a_;
  // Blend formats only, per n code: the second bank (-1: none), a2, the weight t and each read's
  // domain end in radians of a |psi| (pi/2 2^-shift).
  std::vector<int> bank2_;
  std::vector<double> a2_, t_, end1_, end2_;
  Budget budget_;
  std::vector<double> dk_;   // max |d/dx cos^k x| per bank
  std::vector<double> d2k_;  // max |d^2/dx^2 cos^k x| per bank
  std::vector<int> bank_;    // decoder 10 per n code from Format::bank_max_n (-1: invalid), no search per span
  std::vector<double> xe_;   // epicenter end x_e(n) per n code (docs/metrics.md)
  struct {
    double lsb, half_step, interp, coef_err, trunc, rom_lsb;
  } k_{};  // the format's constants (checks.cpp)
  // Per-line scratch of check_line (reused to avoid allocations per line).
  mutable std::vector<uint32_t> golden_;
  mutable std::vector<double> psi_, ref_b_, ref_c_;
};

}  // namespace specular::sim
