// SPDX-License-Identifier: Apache-2.0
//
// rtl/setup/setup.f: the scanline setup in hardware, specular_setup and its blocks
// (docs/setup_hw.md).
//
// Generated from rtl/setup/setup.manifest by `make filelists` (scripts/rtl_filelist.py): edit
// the manifest, not this file. Flat: each include directory and source once, in compile order,
// paths relative to the repository root; run the tools from the root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/setup/setup.f --top-module specular_setup
//   iverilog -g2012 -c rtl/setup/setup.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

+incdir+rtl/prim
// rtl/prim/prim.manifest
rtl/prim/specular_pkg.sv
rtl/prim/specular_delay.sv
rtl/prim/specular_mul_tile.sv
rtl/prim/specular_pipe_mul.sv
rtl/prim/specular_rom.sv
rtl/prim/specular_out_buf.sv
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
