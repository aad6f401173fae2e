// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Stage counts of phong_stream, the per-pixel Blinn-Phong competitor core
// (docs/phong_hw.md#pipeline): one definition, used by the blocks (which check the stages
// they build) and by the top (its PipeDepth). Every multiplier is phong_mul: one register
// of a, 3a and b, then specular_pipe_mul's radix-4 tree.

package phong_pkg;

  // The even exponent of x (the largest even e with 2^e <= x; 0 for x = 0): where the
  // mantissas of |a|^2 and |b|^2 start (phong_norm, phong_cross; x holds 2 op_bits <= 60 bits).
  function automatic int even_exp(input logic [63:0] x);
    even_exp = 0;
    for (int b = 0; b < 64; b++) begin
      if (x[b]) even_exp = b & ~1;
    end
  endfunction

  // Stage 0 of the pixel pipeline: the accumulators A_i, B_i (phong_stream).
  localparam int AccStages = 1;

  // phong_mul over a b_bits-wide operand b.
  function automatic int mul_stages(input int b_bits);
    mul_stages = 1 + specular_pkg::pipe_mul_stages(b_bits);
  endfunction

  // phong_span_setup: the input register, differences / magnitudes / k, the headroom and its
  // shift (the cross form only), the multiplier L * |N1| over the vec_bits-wide magnitude, the sign.
  function automatic int setup_stages(input int vec_bits, input bit headroom);
    setup_stages = 2 + (headroom ? 2 : 0) + mul_stages(vec_bits) + 1;
  endfunction

  // phong_dot: magnitudes, the nine products, the negation and two additions.
  function automatic int dot_stages(input int op_bits);
    dot_stages = 1 + mul_stages(op_bits) + 3;
  endfunction

  // One Newton-Raphson step: y*y, mm*t, 3 - u, y*v.
  function automatic int newton_stages(input int norm_bits);
    newton_stages = 2 * mul_stages(norm_bits) + 1 + mul_stages(norm_bits + 2);
  endfunction

  // phong_norm: exponents, mantissas, ma*mb, mm and the ROM address, the rsqrt ROM read,
  // the Newton steps, dn*y, the clamp.
  function automatic int norm_stages(input int norm_bits, input int newton);
    norm_stages = 2 + mul_stages(norm_bits) + 1 + 1 + newton * newton_stages(norm_bits)
                  + mul_stages(norm_bits) + 1;
  endfunction

  // phong_exp2 (both forms, after w): n*w; the exp2 ROM read, du*t, rounding, u - step, the shift;
  // scale*p and rounding.
  function automatic int exp2_stages(input int w_bits, input int exp_frac_bits, input int exp_bits);
    exp2_stages = mul_stages(w_bits) + 1 + mul_stages(exp_frac_bits) + 3 + mul_stages(exp_bits + 1) + 1;
  endfunction

  // phong_log2 (the textbook form's c -> w): the exponent of c, the mantissa, the log2 ROM
  // read, dv*t, rounding, v + step, w.
  function automatic int log2_stages(input int log_frac_bits);
    log2_stages = 3 + mul_stages(log_frac_bits) + 3;
  endfunction

  // phong_cross (the cancellation-free form): the bits of w = -log2 cos, LogBits fraction
  // bits and the integer part of the largest w, (K + 1) with K <= 2 op_bits - 1.
  function automatic int cross_w_bits(input int op_bits, input int log_bits);
    cross_w_bits = $clog2(2 * op_bits + 1) + log_bits;
  endfunction

  // phong_cross: the reciprocal (dv*t, rounding, v - step) beside the squares of u', d' and
  // su's two additions and the sine test; the longer of the two.
  function automatic int cross_rcp_sq_stages(input int rcp_frac_bits, input int u_bits);
    cross_rcp_sq_stages = mul_stages(rcp_frac_bits) + 2 > mul_stages(u_bits) + 3 ? mul_stages(rcp_frac_bits) + 2
                                                                                 : mul_stages(u_bits) + 3;
  endfunction

  // phong_cross: exponents, mantissas, ma*mb, em, the reciprocal ROM read, the reciprocal and
  // the squares, X*r, s and ep, the mantissa of P, the g and log2 ROM read, dv*t, rounding,
  // v + step, s*gv, w.
  function automatic int cross_stages(input int norm_bits, input int rcp_frac_bits, input int u_bits,
                                      input int rcp_bits, input int g_frac_bits, input int log_frac_bits,
                                      input int g_bits);
    cross_stages = 2 + mul_stages(norm_bits) + 2 + cross_rcp_sq_stages(rcp_frac_bits, u_bits)
                   + mul_stages(rcp_bits + 1) + 3
                   + mul_stages(g_frac_bits > log_frac_bits ? g_frac_bits : log_frac_bits) + 2
                   + mul_stages(g_bits + 1) + 1;
  endfunction

  // phong_stream's pixel pipeline, the accumulators to the last stage before the output
  // buffer (its PipeDepth; the span pipe, setup_stages, runs ahead of it): the accumulators,
  // phong_dot, the form's stages to w (to_w_stages) and phong_exp2.
  function automatic int pipe_depth(input int op_bits, input int to_w_stages, input int exp2);
    pipe_depth = AccStages + dot_stages(op_bits) + to_w_stages + exp2;
  endfunction

endpackage
