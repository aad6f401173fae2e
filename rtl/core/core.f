// SPDX-License-Identifier: Apache-2.0
//
// rtl/core/core.f: the device core, patent UA 71489 blocks 1-14 (docs/device.md), specular_stream and specular_unit.
// Format and use: rtl/README.md#filelists.

-f rtl/prim/prim.f
+incdir+rtl/core
// patent blocks 1-14
rtl/core/specular_reg.sv
rtl/core/specular_down_counter.sv
rtl/core/specular_accumulator.sv
rtl/core/specular_coef_rom.sv
rtl/core/specular_decoder.sv
rtl/core/specular_angle_mul.sv
rtl/core/specular_cos_k_rom.sv
rtl/core/specular_intensity_mul.sv
rtl/core/specular_control.sv
// top levels: the streaming core, the register interface
rtl/core/specular_stream.sv
rtl/core/specular_unit.sv
