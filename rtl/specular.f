// SPDX-License-Identifier: Apache-2.0
//
// rtl/specular.f: the synthesizable sources of the core in compile order (leaf modules
// first, top levels last). One path per line, relative to the repository root; a line
// `+incdir+DIR` names an include directory (for `include files, .svh); `//` comment
// lines and blank lines are ignored. The package specular_pkg (the stage counts) comes
// first: every module refers to it.
// Every build, lint, synthesis, formal and place-and-route flow of this repository reads
// this file; how to use it elsewhere (Verilator, Icarus, Vivado, Quartus, FuseSoC, a
// Makefile) is in rtl/README.md. The ctest rtl_filelist fails when an .sv file under
// rtl/ (outside rtl/formal/ and rtl/fpga/) is missing here or a line names no file.
// The ROM files are read with $readmemh at elaboration, paths relative to the working
// directory (the parameters CoefRomFile and CosRomFile; roms/README.md).

+incdir+rtl
// the package
rtl/specular_pkg.sv
// helpers
rtl/specular_delay.sv
rtl/specular_pipe_mul.sv
rtl/specular_rom.sv
// patent blocks 1-14 and the output buffer
rtl/specular_reg.sv
rtl/specular_down_counter.sv
rtl/specular_accumulator.sv
rtl/specular_coef_rom.sv
rtl/specular_decoder.sv
rtl/specular_angle_mul.sv
rtl/specular_cos_k_rom.sv
rtl/specular_intensity_mul.sv
rtl/specular_control.sv
rtl/specular_out_buf.sv
// the setup in hardware (docs/setup_hw.md): its package and blocks
rtl/specular_setup_pkg.sv
rtl/specular_setup_norm.sv
rtl/specular_setup_cordic.sv
rtl/specular_setup_log2.sv
rtl/specular_setup_exp2.sv
// top levels: the streaming core, the register interface, the AXI wrappers
rtl/specular_stream.sv
rtl/specular_unit.sv
rtl/specular_axis.sv
rtl/specular_axil.sv
// the per-pixel Blinn-Phong competitor on the geometry span interface (docs/phong_hw.md)
rtl/phong_pkg.sv
rtl/phong_mul.sv
rtl/phong_span_setup.sv
rtl/phong_dot.sv
rtl/phong_norm.sv
rtl/phong_pow.sv
rtl/phong_stream.sv
rtl/specular_setup.sv
rtl/specular_system.sv
