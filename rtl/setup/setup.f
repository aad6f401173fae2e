// SPDX-License-Identifier: Apache-2.0
//
// rtl/setup/setup.f: the scanline setup in hardware, specular_setup and its blocks (docs/setup_hw.md).
// Format and use: rtl/README.md#filelists.

-f rtl/prim/prim.f
rtl/setup/specular_setup_pkg.sv
rtl/setup/specular_setup_prio.sv
rtl/setup/specular_setup_rshift.sv
rtl/setup/specular_setup_rshift_n.sv
rtl/setup/specular_setup_norm.sv
rtl/setup/specular_setup_cordic.sv
rtl/setup/specular_setup_cordic_fold.sv
rtl/setup/specular_setup_log2.sv
rtl/setup/specular_setup_exp2.sv
rtl/setup/specular_setup.sv
rtl/setup/specular_setup_lean_pkg.sv
rtl/setup/specular_setup_fmul.sv
rtl/setup/specular_setup_smul.sv
rtl/setup/specular_setup_lean_block.sv
rtl/setup/specular_setup_lean_norm.sv
rtl/setup/specular_setup_lean_cordic.sv
rtl/setup/specular_setup_lean.sv
