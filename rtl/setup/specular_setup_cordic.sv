// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_cordic: CORDIC vectoring, pipelined, one vector per clock
// (docs/setup_hw.md#datapath, step 6; the golden model is host::fixed::cordic_vectoring in
// model/host/setup_fixed.hpp). For (x, y) in Q50 (specular_setup_pkg::CordicFrac) it gives
// angle_o = atan2(y, x) in (-pi, pi] up to the residual atan(2^-(CordicIters-1)), Q50, and
// mag_o = K |(x, y)|, Q50, K the CORDIC gain. |x|, |y| <= 2 in, so every value stays below 8.
//
//   stage 1        a half turn into the right half plane when x < 0 (angle +-pi)
//   stage 2 + i    iteration i: the vector turned by -+atan(2^-i) towards y = 0
// Stages: specular_setup_pkg::CordicStages. en_i freezes every stage. No reset.
//
// Each register of a stage has one adder whose operand the sign inverts (add_sub), not two
// sums and a multiplexer (docs/setup_hw.md#the-cordics-adders).

`include "specular_assert.svh"

module specular_setup_cordic (
  input  logic                                      clk_i,
  input  logic                                      en_i,
  input  logic signed [specular_setup_pkg::CordicW-1:0] x_i,
  input  logic signed [specular_setup_pkg::CordicW-1:0] y_i,
  output logic signed [specular_setup_pkg::CordicW-1:0] angle_o,
  output logic signed [specular_setup_pkg::CordicW-1:0] mag_o
);

  localparam int W      = specular_setup_pkg::CordicW;
  localparam int Iters  = specular_setup_pkg::CordicIters;
  localparam logic signed [W-1:0] Pi = W'(specular_setup_pkg::Pi);
  localparam int Stages = 1 + Iters;

  if (Stages != specular_setup_pkg::CordicStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_cordic: specular_setup_pkg::CordicStages disagrees with the stages built here")
  end

  // a + b when sub = 0, a - b when sub = 1, modulo 2^W: one adder, b inverted and the carry in
  // set by sub (docs/setup_hw.md#the-cordics-adders).
  function automatic logic [W-1:0] add_sub(input logic [W-1:0] a, input logic [W-1:0] b,
                                           input logic sub);
    add_sub = a + (b ^ {W{sub}}) + {{(W-1){1'b0}}, sub};
  endfunction

  // x_q[j], y_q[j], z_q[j]: after stage j + 1 (j = 0: the half turn).
  logic signed [W-1:0] x_q [Iters+1], y_q [Iters+1], z_q [Iters+1];

  // Stage 1: (x, y) negated when x < 0 (0 - v as 0 + ~v + 1); the angle starts at +-pi.
  logic                neg_in;
  logic signed [W-1:0] x_in_d, y_in_d, z_in_d;
  assign neg_in = x_i[W-1];
  assign x_in_d = add_sub('0, x_i, neg_in);
  assign y_in_d = add_sub('0, y_i, neg_in);
  assign z_in_d = !neg_in ? '0 : (!y_i[W-1] ? Pi : -Pi);

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      x_q[0] <= x_in_d;
      y_q[0] <= y_in_d;
      z_q[0] <= z_in_d;
    end
  end

  for (genvar i = 0; i < Iters; i++) begin : gen_iter
    localparam logic signed [W-1:0] Atan = W'(specular_setup_pkg::atan_q(i));
    // up: y < 0, the vector turns up: x - dx, y + dy, z - Atan (else x + dx, y - dy, z + Atan).
    logic                up;
    logic signed [W-1:0] dx, dy, x_d, y_d, z_d;
    assign up  = y_q[i][W-1];
    assign dx  = y_q[i] >>> i;
    assign dy  = x_q[i] >>> i;
    assign x_d = add_sub(x_q[i], dx, up);
    assign y_d = add_sub(y_q[i], dy, !up);
    assign z_d = add_sub(z_q[i], Atan, up);
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        x_q[i+1] <= x_d;
        y_q[i+1] <= y_d;
        z_q[i+1] <= z_d;
      end
    end
  end

  assign angle_o = z_q[Iters];
  assign mag_o   = x_q[Iters];

  // y_q[Iters] is the residual, unused.
  logic unused_y;
  assign unused_y = ^y_q[Iters];

endmodule
