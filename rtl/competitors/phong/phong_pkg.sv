// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Stage counts of phong_stream, the per-pixel Blinn-Phong competitor core
// (docs/phong_hw.md#pipeline): one definition, used by the blocks (which check the stages
// they build) and by the top (its PipeDepth). Every multiplier is phong_mul: one register
// of a, 3a and b, then specular_pipe_mul's radix-4 tree.

package phong_pkg;

  // Stage 0 of the pixel pipeline: the accumulators A_i, B_i (phong_stream).
  localparam int AccStages = 1;

  // phong_mul over a b_bits-wide operand b.
  function automatic int mul_stages(input int b_bits);
    mul_stages = 1 + specular_pkg::pipe_mul_stages(b_bits);
  endfunction

  // phong_span_setup: the input register, differences / magnitudes / k, the multiplier
  // L * |N1| over the vec_bits-wide magnitude, the sign.
  function automatic int setup_stages(input int vec_bits);
    setup_stages = 2 + mul_stages(vec_bits) + 1;
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

  // phong_pow: the exponent of c, the mantissa, the log2 ROM read, dv*t, rounding, v + step,
  // w; n*w; the exp2 ROM read, du*t, rounding, u - step, the shift; scale*p and rounding.
  function automatic int pow_stages(input int log_frac_bits, input int w_bits, input int exp_frac_bits,
                                    input int exp_bits);
    pow_stages = 3 + mul_stages(log_frac_bits) + 3 + mul_stages(w_bits) + 1 + mul_stages(exp_frac_bits) + 3
                 + mul_stages(exp_bits + 1) + 1;
  endfunction

  // phong_stream's pixel pipeline, the accumulators to the last stage before the output
  // buffer (its PipeDepth; the span pipe, setup_stages, runs ahead of it).
  function automatic int pipe_depth(input int op_bits, input int norm_bits, input int newton,
                                    input int log_frac_bits, input int w_bits, input int exp_frac_bits,
                                    input int exp_bits);
    pipe_depth = AccStages + dot_stages(op_bits) + norm_stages(norm_bits, newton)
                 + pow_stages(log_frac_bits, w_bits, exp_frac_bits, exp_bits);
  endfunction

endpackage
