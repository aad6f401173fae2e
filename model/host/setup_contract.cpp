// SPDX-License-Identifier: Apache-2.0
// The setup's contract, docs/setup_hw.md#the-contract.
#include "setup_contract.hpp"

#include "setup_fixed.hpp"

#include <cmath>

namespace specular::host {

SetupRule hardware_rule() {
  SetupRule r;
  r.hardware = true;
  r.q_min = std::ldexp(1.0, -fixed::kOppNormLog2);
  r.flat_sin = std::ldexp(1.0, -fixed::kFlatLog2 / 2);
  r.opposite_sin = std::ldexp(1.0, -fixed::kOppHalfLog2 / 2);
  return r;
}

ContractCheck check_contract(const device::GeoSpan& g, SetupStatus hw_status, const Decisions& hw_took, const device::Registers& hw,
                             const device::GeoFormat& gf, const device::Format& f) {
  ContractCheck out;
  const ScanlineInput in = device::geo_input(g, gf, f);
  SetupRule rule = hardware_rule();
  auto band = [](double metric, double threshold) { return metric >= threshold / 2 && metric <= threshold * 2; };
  auto force = [](bool took) { return took ? SetupRule::Force::yes : SetupRule::Force::no; };
  ScanlineSetup s = scanline_setup(in, rule);
  const bool decoded = s.status == SetupStatus::invalid_input || s.status == SetupStatus::undefined_halfway;
  if (!decoded) {
    // The normals first: the halfway decisions depend on the H2 they give.
    if (band(s.q, rule.q_min)) {
      rule.opposite_normals = force(hw_took.opposite_normals);
      ++out.in_band;
      s = scanline_setup(in, rule);
    }
    if (s.x_positive && band(s.sin_gamma, rule.flat_sin)) {
      rule.flat = force(hw_took.flat);
      ++out.in_band;
    }
    if (!s.x_positive && band(s.sin_gamma, rule.opposite_sin)) {
      rule.opposite_halfway = force(hw_took.opposite_halfway);
      ++out.in_band;
    }
    s = scanline_setup(in, rule);
  }
  out.ref_status = s.status;
  out.ref_flat = s.flat;
  // A one-pixel span's pixel does not depend on N2 or He: only the decode's statuses count.
  const auto decode_only = [](SetupStatus st) {
    return st == SetupStatus::invalid_input || st == SetupStatus::undefined_halfway ? st : SetupStatus::ok;
  };
  out.decisions_equal = g.len == 0 ? decode_only(s.status) == decode_only(hw_status)
                                   : s.status == hw_status && (decoded || s.flat == hw_took.flat);
  out.ref = device::load_registers(s, in.n, in.l, f).reg;
  out.ref_setup = s;
  out.pixels = compare_pixels(hw, out.ref, f);
  return out;
}

}  // namespace specular::host
