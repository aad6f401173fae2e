// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_cordic: CORDIC vectoring, angle only, pipelined, one vector per clock:
// host::fixed::cordic_angle (model/host/setup_fixed.cpp; docs/setup_hw.md#the-datapath,
// step 6). angle_o = atan2(y, x) in (-pi, pi] up to the residual, Q(Frac), for (x, y) in
// Q(Frac); x, y, z are W-bit registers (the model checks that they never wrap). The
// magnitude is not needed (A^2 is computed exactly), so x's last iteration is not built.
//
//   stage 1      a half turn into the right half plane when x < 0 (angle +-pi)
//   stage 2 + i  iteration i: the vector turned by -+atan(2^-i) towards y = 0
// Stages: 1 + Iters (specular_setup_pkg::CordicStages). en_i freezes every stage. No reset.
//
// As specular_setup_cordic, each register has one adder whose operand the direction inverts
// (add_sub), not two sums and a multiplexer (docs/setup_hw.md#the-cordics-adders).

`include "specular_assert.svh"

module specular_setup_cordic #(
  parameter int W     = specular_setup_pkg::CordicW,
  parameter int Iters = specular_setup_pkg::CordicIters
) (
  input  logic                clk_i,
  input  logic                en_i,
  input  logic signed [W-1:0] x_i,
  input  logic signed [W-1:0] y_i,
  output logic signed [W-1:0] angle_o
);

  localparam logic signed [W-1:0] Pi = W'(specular_setup_pkg::Pi);

  if (Iters < 2 || Iters > specular_setup_pkg::CordicIters) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup_cordic: Iters must be in 2..CordicIters (the atan words of the package)")
  end
  if (1 + Iters != specular_setup_pkg::CordicStages && Iters == specular_setup_pkg::CordicIters) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_cordic: CordicStages disagrees with the stages built here")
  end

  // a + b when sub = 0, a - b when sub = 1, modulo 2^W: one adder.
  function automatic logic [W-1:0] add_sub(input logic [W-1:0] a, input logic [W-1:0] b, input logic sub);
    add_sub = a + (b ^ {W{sub}}) + {{(W-1){1'b0}}, sub};
  endfunction

  // x_q[j], y_q[j], z_q[j]: after stage j + 1 (j = 0: the half turn).
  logic signed [W-1:0] x_q [Iters], y_q [Iters], z_q [Iters+1];

  logic neg_in;
  assign neg_in = x_i[W-1];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      x_q[0] <= add_sub('0, x_i, neg_in);
      y_q[0] <= add_sub('0, y_i, neg_in);
      z_q[0] <= !neg_in ? '0 : (!y_i[W-1] ? Pi : -Pi);
    end
  end

  for (genvar i = 0; i < Iters; i++) begin : gen_iter
    localparam logic signed [63:0] AtanWord = specular_setup_pkg::atan_word(i);
    localparam logic signed [W-1:0] Atan = AtanWord[W-1:0];  // (a cast of a call: not Icarus 11)
    // up: y < 0, the vector turns up: x - dx, y + dy, z - Atan (else x + dx, y - dy, z + Atan).
    logic up;
    assign up = y_q[i][W-1];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        z_q[i+1] <= add_sub(z_q[i], Atan, up);
      end
    end
    if (i + 1 < Iters) begin : gen_xy
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          x_q[i+1] <= add_sub(x_q[i], y_q[i] >>> i, up);
          y_q[i+1] <= add_sub(y_q[i], x_q[i] >>> i, !up);
        end
      end
    end
  end

  assign angle_o = z_q[Iters];

endmodule
