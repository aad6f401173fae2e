// SPDX-License-Identifier: Apache-2.0
//
// rtl/system/system.f: specular_system, geometry spans in and pixels out: the setup, then the
// core (docs/system.md).
//
// Generated from rtl/system/system.manifest by `make filelists` (scripts/rtl_filelist.py): edit
// the manifest, not this file. Flat: each include directory and source once, in compile order,
// paths relative to the repository root; run the tools from the root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/system/system.f --top-module specular_system
//   iverilog -g2012 -c rtl/system/system.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

+incdir+rtl/prim
+incdir+rtl/core
// rtl/prim/prim.manifest
rtl/prim/specular_pkg.sv
rtl/prim/specular_delay.sv
rtl/prim/specular_mul_tile.sv
rtl/prim/specular_pipe_mul.sv
rtl/prim/specular_rom.sv
rtl/prim/specular_out_buf.sv
// rtl/core/core.manifest
rtl/core/specular_reg.sv
rtl/core/specular_down_counter.sv
rtl/core/specular_accumulator.sv
rtl/core/specular_coef_rom.sv
rtl/core/specular_decoder.sv
rtl/core/specular_angle_mul.sv
rtl/core/specular_cos_k_rom.sv
rtl/core/specular_blend.sv
rtl/core/specular_intensity_mul.sv
rtl/core/specular_control.sv
rtl/core/specular_stream.sv
rtl/core/specular_unit.sv
// rtl/setup/setup.manifest
rtl/setup/specular_setup_pkg.sv
rtl/setup/specular_setup_prio.sv
rtl/setup/specular_setup_rshift.sv
rtl/setup/specular_setup_rshift_n.sv
rtl/setup/specular_setup_cordic_fold.sv
rtl/setup/specular_setup_log2.sv
rtl/setup/specular_setup_fmul.sv
rtl/setup/specular_setup_smul.sv
rtl/setup/specular_setup_exp2.sv
rtl/setup/specular_setup_block.sv
rtl/setup/specular_setup_norm.sv
rtl/setup/specular_setup_cordic.sv
rtl/setup/specular_setup.sv
// rtl/system/system.manifest
rtl/system/specular_system.sv
