// SPDX-License-Identifier: Apache-2.0
//
// rtl/competitors/phong/phong.f: phong_stream, the per-pixel Blinn-Phong competitor (docs/phong_hw.md); a benchmark baseline, not part of the product (rtl/specular.f).
// Format and use: rtl/README.md#filelists.

-f rtl/core/core.f
rtl/competitors/phong/phong_pkg.sv
rtl/competitors/phong/phong_mul.sv
rtl/competitors/phong/phong_span_setup.sv
rtl/competitors/phong/phong_dot.sv
rtl/competitors/phong/phong_norm.sv
rtl/competitors/phong/phong_exp2.sv
rtl/competitors/phong/phong_log2.sv
rtl/competitors/phong/phong_cross.sv
rtl/competitors/phong/phong_stream.sv
