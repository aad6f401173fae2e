// SPDX-License-Identifier: Apache-2.0
//
// rtl/prim/prim.f: the shared primitives (the stage-count package specular_pkg, delay line, DSP
// tile, pipelined multiplier, ROM, output buffer, assertion macros).
//
// Generated from rtl/prim/prim.manifest by `make filelists` (scripts/rtl_filelist.py): edit the
// manifest, not this file. Flat: each include directory and source once, in compile order,
// paths relative to the repository root; run the tools from the root (rtl/README.md#filelists):
//   verilator --lint-only -Wall -f rtl/prim/prim.f --top-module specular_delay
//   iverilog -g2012 -c rtl/prim/prim.f -s TOP   (which IPs Icarus 11 elaborates: rtl/README.md#filelists)

+incdir+rtl/prim
// rtl/prim/prim.manifest
rtl/prim/specular_pkg.sv
rtl/prim/specular_delay.sv
rtl/prim/specular_mul_tile.sv
rtl/prim/specular_pipe_mul.sv
rtl/prim/specular_rom.sv
rtl/prim/specular_out_buf.sv
