// SPDX-License-Identifier: Apache-2.0
//
// rtl/prim/prim.f: the shared primitives (the stage-count package specular_pkg, delay line, DSP tile, pipelined multiplier, ROM, output buffer, assertion macros).
// Format and use: rtl/README.md#filelists.

+incdir+rtl/prim
rtl/prim/specular_pkg.sv
rtl/prim/specular_delay.sv
rtl/prim/specular_mul_tile.sv
rtl/prim/specular_pipe_mul.sv
rtl/prim/specular_rom.sv
rtl/prim/specular_out_buf.sv
