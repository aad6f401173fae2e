// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Pipelined unsigned multiplier p = a * b of phong_stream: one register holding a, 3a (the
// one carry chain of the stage) and b, then specular_pipe_mul's radix-4 tree. Latency
// phong_pkg::mul_stages(BBits); en_i freezes every stage. No reset (datapath only).
// TileBits picks specular_pipe_mul's resources, LUT tree or DSP tiles of the same latency
// (docs/pipeline.md#multiplier-styles); the tiles take no 3a, so synthesis drops its adder.

`include "specular_assert.svh"

module phong_mul #(
  parameter int ABits    = 16,
  parameter int BBits    = 16,
  parameter int TileBits = 0    // 0: LUT tree; else the DSP tile width (16 UP5K, 18 ECP5)
) (
  input  logic                   clk_i,
  input  logic                   en_i,
  input  logic [ABits-1:0]       a_i,
  input  logic [BBits-1:0]       b_i,
  output logic [ABits+BBits-1:0] p_o
);

  if (ABits < 1 || BBits < 2) begin : gen_width_check
    `SPEC_PARAM_ERROR("phong_mul: ABits must be >= 1 and BBits >= 2")
  end

  // The latency, public so that the block test takes it from phong_pkg instead of a copy;
  // nothing in the module reads it.
  /* verilator lint_off UNUSEDPARAM */
  localparam int Stages /*verilator public*/ = phong_pkg::mul_stages(BBits);
  /* verilator lint_on UNUSEDPARAM */

  logic [ABits-1:0] a_q;
  logic [ABits+1:0] a3_q;
  logic [BBits-1:0] b_q;

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      a_q  <= a_i;
      a3_q <= (ABits + 2)'(a_i) + ((ABits + 2)'(a_i) << 1);
      b_q  <= b_i;
    end
  end

  specular_pipe_mul #(
    .ABits    (ABits),
    .BBits    (BBits),
    .TileBits (TileBits)
  ) u_tree (
    .clk_i (clk_i),
    .en_i  (en_i),
    .a_i   (a_q),
    .a3_i  (a3_q),
    .b_i   (b_q),
    .p_o   (p_o)
  );

endmodule
