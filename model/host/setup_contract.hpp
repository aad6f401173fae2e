// SPDX-License-Identifier: Apache-2.0
// The contract of the hardware setup (docs/setup_hw.md#the-contract): the reference is the
// scalar double setup on the exact values of the codes under the hardware's stated rule
// (thresholds on |N1 + N2|^2 and sin gamma); inside a decision's guard band (a factor of 2 on
// its metric) either outcome is accepted and the reference takes the hardware's branch;
// outside, the status and the flat flag must be equal (on a one-pixel span, whose pixel does
// not depend on N2 or He, only the decode's statuses). The registers are then compared as
// pixels: within 0.01 % in the epicenter (0.01 % of C elsewhere) + 1 LSB (compare_pixels).
#pragma once

#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"
#include "setup_batch.hpp"

namespace specular::host {

// The setup's rule (the thresholds of host::fixed, as values of the exact metrics).
SetupRule hardware_rule();

struct ContractCheck {
  SetupStatus ref_status = SetupStatus::ok;
  bool ref_flat = false;
  bool decisions_equal = true;  // status and flat flag, after the guard bands
  int in_band = 0;              // decisions that fell inside a guard band
  ScanlineSetup ref_setup;      // the reference setup in the branch taken (the end-to-end truth)
  device::Registers ref;        // its registers
  PixelAgreement pixels;
  bool ok() const { return decisions_equal && pixels.ok(); }
};

// The three decisions a hardware setup takes (opposite_normals and opposite_halfway may both
// hold; the status then says opposite_halfway).
struct Decisions {
  bool opposite_normals = false, flat = false, opposite_halfway = false;
};
// `hw_status`, `hw_took`, `hw`: what the hardware setup gave for span `g`.
ContractCheck check_contract(const device::GeoSpan& g, SetupStatus hw_status, const Decisions& hw_took, const device::Registers& hw,
                             const device::GeoFormat& gf, const device::Format& f);

}  // namespace specular::host
