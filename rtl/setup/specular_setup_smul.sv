// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_smul: an exact signed product p = a * b on the unsigned pipelined multiplier
// specular_pipe_mul, one pair per clock (docs/setup_hw.md#the-lean-datapath: every product of
// the lean setup goes through one). Signs are taken off before the multiplier and put back
// after it, so the multiplier stays unsigned and its stages keep one carry chain each.
//
//   first stage   |a|, |b|, the sign of the product
//   second stage  3|a| (the LUT tree's digit row; not built with DSP tiles)
//   then          specular_pipe_mul (specular_pkg::pipe_mul_stages(BBits))
//   last stage    the sign put back (negate or not)
// Stages: specular_setup_lean_pkg::smul_stages(BBits, SetupII). en_i freezes every stage.
// No reset. With SetupII > 1 (the folded setup, en_i once per slot) the product is a
// one-product specular_setup_fmul instead: one stage, one tile multiplier.

module specular_setup_smul #(
  parameter int ABits    = 18,
  parameter int BBits    = 18,
  parameter int TileBits = 18,  // specular_pipe_mul's: 0 LUT tree, 18 ECP5 MULT18X18D tiles
  parameter int SetupII  = 1
) (
  input  logic                           clk_i,
  input  logic                           en_i,
  input  logic signed [ABits-1:0]        a_i,
  input  logic signed [BBits-1:0]        b_i,
  output logic signed [ABits+BBits-1:0]  p_o
);

  if (SetupII > 1) begin : gen_fold
    logic [ABits+BBits-1:0] pc_unused;  // p_o is the registered product
    specular_setup_fmul #(.N(1), .ABits(ABits), .BBits(BBits), .TileBits(TileBits), .SetupII(SetupII)) u_fmul (
      .clk_i (clk_i), .en_i (en_i), .a_i (a_i), .b_i (b_i), .p_o (p_o), .pc_o (pc_unused));
  end else begin : gen_pipe
    localparam int PBits  = ABits + BBits;
    localparam int Levels = specular_setup_lean_pkg::pipe_mul_stages(BBits);

    // Stage 1: magnitudes (|-2^(n-1)| = 2^(n-1) still fits n unsigned bits).
    logic [ABits-1:0] ma_q, a2_q;
    logic [BBits-1:0] mb_q, b2_q;
    logic [ABits+1:0] a3_q;
    logic             neg_q, neg2_q, neg_p;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        ma_q   <= a_i[ABits-1] ? ABits'(-a_i) : ABits'(a_i);
        mb_q   <= b_i[BBits-1] ? BBits'(-b_i) : BBits'(b_i);
        neg_q  <= a_i[ABits-1] ^ b_i[BBits-1];
        // stage 2
        a2_q   <= ma_q;
        b2_q   <= mb_q;
        neg2_q <= neg_q;
      end
    end
    // 3|a| only for the LUT tree: the DSP style never reads it, and a hierarchical synthesis
    // (synth_ecp5 -noflatten) keeps a register that feeds another module's unread port.
    if (TileBits == 0) begin : gen_a3
      always_ff @(posedge clk_i) begin
        if (en_i) a3_q <= (ABits + 2)'(ma_q) + ((ABits + 2)'(ma_q) << 1);
      end
    end else begin : gen_no_a3
      assign a3_q = '0;
    end

    logic [PBits-1:0] mag;
    specular_pipe_mul #(.ABits(ABits), .BBits(BBits), .TileBits(TileBits)) u_mul (
      .clk_i (clk_i), .en_i (en_i), .a_i (a2_q), .a3_i (a3_q), .b_i (b2_q), .p_o (mag)
    );
    specular_delay #(.Width(1), .Depth(Levels), .Reset(1'b0)) u_dly_neg (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (neg2_q), .q_o (neg_p)
    );

    always_ff @(posedge clk_i) begin
      if (en_i) begin
        p_o <= neg_p ? -$signed(mag) : $signed(mag);
      end
    end

  end

endmodule
