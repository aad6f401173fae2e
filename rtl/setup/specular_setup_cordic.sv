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

  // x_q[j], y_q[j], z_q[j]: after stage j + 1 (j = 0: the half turn).
  logic signed [W-1:0] x_q [Iters+1], y_q [Iters+1], z_q [Iters+1];

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (x_i < 0) begin
        x_q[0] <= -x_i;
        y_q[0] <= -y_i;
        z_q[0] <= y_i >= 0 ? Pi : -Pi;
      end else begin
        x_q[0] <= x_i;
        y_q[0] <= y_i;
        z_q[0] <= '0;
      end
    end
  end

  for (genvar i = 0; i < Iters; i++) begin : gen_iter
    localparam logic signed [W-1:0] Atan = W'(specular_setup_pkg::atan_q(i));
    logic signed [W-1:0] dx, dy;
    assign dx = y_q[i] >>> i;
    assign dy = x_q[i] >>> i;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        if (y_q[i] >= 0) begin
          x_q[i+1] <= x_q[i] + dx;
          y_q[i+1] <= y_q[i] - dy;
          z_q[i+1] <= z_q[i] + Atan;
        end else begin
          x_q[i+1] <= x_q[i] - dx;
          y_q[i+1] <= y_q[i] + dy;
          z_q[i+1] <= z_q[i] - Atan;
        end
      end
    end
  end

  assign angle_o = z_q[Iters];
  assign mag_o   = x_q[Iters];

  // y_q[Iters] is the residual, unused.
  logic unused_y;
  assign unused_y = ^y_q[Iters];

endmodule
