// SPDX-License-Identifier: Apache-2.0
//
// rtl/competitors/phong/phong.f: phong_stream, the per-pixel Blinn-Phong competitor
// (docs/phong_hw.md); a benchmark baseline, not part of the product.
//
// Generated from rtl/competitors/phong/phong.manifest by `make filelists`
// (scripts/rtl_filelist.py): edit the manifest, not this file. Flat: each include directory and
// source once, in compile order, paths relative to the repository root; run the tools from the
// root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/competitors/phong/phong.f --top-module phong_stream
//   iverilog -g2012 -c rtl/competitors/phong/phong.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

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
// rtl/competitors/phong/phong.manifest
rtl/competitors/phong/phong_pkg.sv
rtl/competitors/phong/phong_mul.sv
rtl/competitors/phong/phong_span_setup.sv
rtl/competitors/phong/phong_dot.sv
rtl/competitors/phong/phong_norm.sv
rtl/competitors/phong/phong_exp2.sv
rtl/competitors/phong/phong_log2.sv
rtl/competitors/phong/phong_cross.sv
rtl/competitors/phong/phong_stream.sv
