// SPDX-License-Identifier: Apache-2.0
//
// rtl/axi/axi.f: the AXI wrappers of the core, specular_axis (AXI4-Stream) and specular_axil
// (AXI4-Lite registers, docs/interfaces.md).
//
// Generated from rtl/axi/axi.manifest by `make filelists` (scripts/rtl_filelist.py): edit the
// manifest, not this file. Flat: each include directory and source once, in compile order,
// paths relative to the repository root; run the tools from the root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/axi/axi.f --top-module specular_axis
//   iverilog -g2012 -c rtl/axi/axi.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

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
