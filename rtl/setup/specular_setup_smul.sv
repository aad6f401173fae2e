// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_smul: an exact signed product p = a * b, one pair per clock
// (docs/setup_hw.md#the-datapath: every product of the setup goes through one).
// Stages: specular_setup_pkg::smul_stages(BBits, 1) in every style; en_i freezes every
// stage. No reset. The folded setup (SetupII > 1) takes its products from shared
// specular_setup_fmul units instead.
//
// With DSP tiles (TileBits > 0) the operands wait three stages and go to specular_pipe_mul
// with Signed = 1: cut as specular_setup_fmul cuts them, unsigned low tiles of TileBits - 1
// bits and a signed top tile, so every tile product is one signed TileBits x TileBits product
// and no magnitude or sign is formed around it (a conditional negation of each operand and of
// the product costs about 2 (ABits + BBits) LUT4 and three carry chains a product,
// docs/setup_hw.md#the-rtl).
//
// The LUT tree (TileBits = 0, the iCE40 style) multiplies magnitudes on specular_pipe_mul:
//
//   first stage   |a|, |b|, the sign of the product
//   second stage  3|a| (the tree's digit row)
//   then          specular_pipe_mul (specular_pkg::pipe_mul_stages(BBits))
//   last stage    the sign put back (negate or not)

module specular_setup_smul #(
  parameter int ABits    = 18,
  parameter int BBits    = 18,
  parameter int TileBits = 18   // specular_pipe_mul's: 0 LUT tree, 18 ECP5 MULT18X18D tiles
) (
  input  logic                           clk_i,
  input  logic                           en_i,
  input  logic signed [ABits-1:0]        a_i,
  input  logic signed [BBits-1:0]        b_i,
  output logic signed [ABits+BBits-1:0]  p_o
);

  if (TileBits > 0) begin : gen_dsp
    // The operands wait out the three stages the magnitudes take in the LUT style, then
    // specular_pipe_mul multiplies them as signed tiles.
    localparam int Wait = specular_setup_pkg::smul_stages(BBits, 1)
                        - specular_setup_pkg::pipe_mul_stages(BBits);
    logic [ABits-1:0] a_w;
    logic [BBits-1:0] b_w;
    specular_delay #(.Width(ABits + BBits), .Depth(Wait), .Reset(1'b0)) u_wait (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({a_i, b_i}), .q_o ({a_w, b_w}));
    logic [ABits+BBits-1:0] p;
    specular_pipe_mul #(.ABits(ABits), .BBits(BBits), .TileBits(TileBits), .Signed(1'b1)) u_mul (
      .clk_i (clk_i), .en_i (en_i), .a_i (a_w), .a3_i ({(ABits + 2){1'b0}}), .b_i (b_w), .p_o (p));
    assign p_o = $signed(p);

  end else begin : gen_pipe
    localparam int PBits  = ABits + BBits;
    localparam int Levels = specular_setup_pkg::pipe_mul_stages(BBits);

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
    always_ff @(posedge clk_i) begin
      if (en_i) a3_q <= (ABits + 2)'(ma_q) + ((ABits + 2)'(ma_q) << 1);
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
