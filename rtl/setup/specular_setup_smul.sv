// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_smul: an exact signed product p = a * b, one pair per clock
// (docs/setup_hw.md#the-lean-datapath: every product of the lean setup goes through one).
// Stages: specular_setup_lean_pkg::smul_stages(BBits, SetupII) in every style; en_i freezes
// every stage. No reset.
//
// With DSP tiles (TileBits > 0) the operands are cut as specular_setup_fmul cuts them:
// unsigned low tiles of TileBits - 1 bits and a signed top tile, so every tile product is one
// signed TileBits x TileBits product and no magnitude or sign is formed around it (a
// conditional negation of each operand and of the product costs about 2 (ABits + BBits) LUT4
// and three carry chains a product, docs/setup_hw.md#the-lean-rtl).
//
//   then          the operands wait out the stages the tiles do not need
//   stage         the tiles registered (the DSP's input registers)
//   stage         each tile product registered (its output register)
//   clog2(tiles)  a binary tree of adders, one register a level; the last is p_o
//
// The LUT tree (TileBits = 0, the iCE40 style) multiplies magnitudes on specular_pipe_mul:
//
//   first stage   |a|, |b|, the sign of the product
//   second stage  3|a| (the tree's digit row)
//   then          specular_pipe_mul (specular_pkg::pipe_mul_stages(BBits))
//   last stage    the sign put back (negate or not)
//
// With SetupII > 1 (the folded setup, en_i once per slot) the product is a one-product
// specular_setup_fmul instead: one stage, one tile multiplier.

`include "specular_assert.svh"

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
  end else if (TileBits > 0) begin : gen_dsp
    localparam int T      = TileBits;
    localparam int PBits  = ABits + BBits;
    localparam int TA     = specular_setup_lean_pkg::fmul_tiles_of(ABits, TileBits);
    localparam int TB     = specular_setup_lean_pkg::fmul_tiles_of(BBits, TileBits);
    localparam int TP     = TA * TB;
    localparam int Levels = (TP > 1) ? $clog2(TP) : 0;
    localparam int Wait   = specular_setup_lean_pkg::smul_stages(BBits, SetupII) - 2 - Levels;

    if (T < 2 || Wait < 0) begin : gen_tile_check
      `SPEC_PARAM_ERROR("specular_setup_smul: TileBits must be >= 2, with 2 + clog2(tiles) <= smul_stages(BBits)")
    end

    logic [ABits-1:0] a_w;
    logic [BBits-1:0] b_w;
    specular_delay #(.Width(ABits + BBits), .Depth(Wait), .Reset(1'b0)) u_wait (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({a_i, b_i}), .q_o ({a_w, b_w}));

    // Tile i of an operand: bits (T-1) i .. (T-1) i + T - 2 zero-extended, the top one
    // sign-extended.
    logic [TA*(T-1):0] a_ext;
    logic [TB*(T-1):0] b_ext;
    assign a_ext = (TA * (T - 1) + 1)'($signed(a_w));
    assign b_ext = (TB * (T - 1) + 1)'($signed(b_w));
    logic signed [T-1:0] ta_q [TA];
    logic signed [T-1:0] tb_q [TB];
    for (genvar i = 0; i < TA; i++) begin : gen_ta
      always_ff @(posedge clk_i) begin
        if (en_i) ta_q[i] <= (i == TA - 1) ? a_ext[i*(T-1) +: T] : {1'b0, a_ext[i*(T-1) +: T-1]};
      end
    end
    for (genvar i = 0; i < TB; i++) begin : gen_tb
      always_ff @(posedge clk_i) begin
        if (en_i) tb_q[i] <= (i == TB - 1) ? b_ext[i*(T-1) +: T] : {1'b0, b_ext[i*(T-1) +: T-1]};
      end
    end

    // rows[l][r]: row r after level l; level 0 the tile products at their weights, modulo
    // 2^PBits (the sum is exact there, as the product fits PBits signed bits).
    logic [PBits-1:0] rows [Levels+1][TP];
    for (genvar i = 0; i < TA; i++) begin : gen_pa
      for (genvar j = 0; j < TB; j++) begin : gen_pb
        logic signed [2*T-1:0] pp_q;
        always_ff @(posedge clk_i) begin
          if (en_i) pp_q <= ta_q[i] * tb_q[j];
        end
        logic signed [PBits+2*T-1:0] pp_x;
        assign pp_x = (PBits + 2 * T)'(pp_q);
        assign rows[0][i*TB+j] = PBits'(pp_x <<< ((T - 1) * (i + j)));
      end
    end
    for (genvar l = 1; l <= Levels; l++) begin : gen_level
      localparam int NPrev = (TP + (1 << (l - 1)) - 1) >> (l - 1);
      localparam int NCur  = (TP + (1 << l) - 1) >> l;
      for (genvar r = 0; r < NCur; r++) begin : gen_row
        logic [PBits-1:0] sum_q;
        always_ff @(posedge clk_i) begin
          if (en_i) sum_q <= (2 * r + 1 < NPrev) ? rows[l-1][2*r] + rows[l-1][2*r+1] : rows[l-1][2*r];
        end
        assign rows[l][r] = sum_q;
      end
      for (genvar r = NCur; r < TP; r++) begin : gen_unused_row
        assign rows[l][r] = '0;
      end
    end
    assign p_o = $signed(rows[Levels][0]);

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
