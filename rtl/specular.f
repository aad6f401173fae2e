// SPDX-License-Identifier: Apache-2.0
//
// rtl/specular.f: the specular-intensity device of patent UA 71489, every IP of the product:
// the core, the AXI wrappers, the hardware setup, the system.
//
// Generated from rtl/specular.manifest by `make filelists` (scripts/rtl_filelist.py): edit the
// manifest, not this file. Flat: each include directory and source once, in compile order,
// paths relative to the repository root; run the tools from the root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/specular.f --top-module specular_axil
//   iverilog -g2012 -c rtl/specular.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

+incdir+rtl/prim
+incdir+rtl/core
+incdir+rtl/axi
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
// rtl/axi/axi.manifest
rtl/axi/specular_axil_reg_pkg.sv
rtl/axi/specular_axis.sv
rtl/axi/specular_axil.sv
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
