// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// The dot products of phong_stream (docs/phong_hw.md#design): from the interpolated vectors
// A_i, B_i (AccBits, signed) the operands a = A >> (AccBits - OpBits), b likewise (floor),
// then d = a . b (signed), na = a . a, nb = b . b, exact; with Cross (the cancellation-free
// form, docs/phong_hw.md#the-cancellation-free-form) also u = a x b, exact. Bit-exact contract:
// model/device/phong_model.hpp. phong_pkg::dot_stages(OpBits) stages:
//   1        |a|, |b| and the sign of each product (parallel carry chains)
//   2 ..     nine products (phong_mul: three a.b, three squares of a, three of b), six more
//            with Cross (a_i b_j, i != j)
//   +1       the a.b products negated where their sign is set; na, nb: first additions;
//            u: both products of a component signed (a_i b_j + (-a_j b_i))
//   +2       d: first addition; na, nb: second additions; u: the addition
//   +3       d: second addition

`include "specular_assert.svh"

module phong_dot #(
  parameter int AccBits = 29,
  parameter int OpBits  = 20,
  parameter bit Cross   = 1'b0,
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0
) (
  input  logic                      clk_i,
  input  logic                      en_i,
  input  logic [3*AccBits-1:0]      a_i,
  input  logic [3*AccBits-1:0]      b_i,
  output logic signed [2*OpBits+1:0] d_o,
  output logic [2*OpBits-1:0]       na_o,
  output logic [2*OpBits-1:0]       nb_o,
  // Cross only (else 0): u = a x b, component c at [c*(2*OpBits+1) +: 2*OpBits+1], signed.
  output logic [3*(2*OpBits+1)-1:0] u_o
);

  localparam int MulDepth = phong_pkg::mul_stages(OpBits);
  localparam int PBits    = 2 * OpBits;
  localparam int DBits    = 2 * OpBits + 2;

  if (OpBits < 2 || OpBits > AccBits || phong_pkg::dot_stages(OpBits) != MulDepth + 4) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_dot: 2 <= OpBits <= AccBits; phong_pkg::dot_stages disagrees")
  end

  // ---- stage 1: magnitudes and signs ----
  logic [OpBits-1:0] ma_1 [3], mb_1 [3];
  logic [2:0]        s_1, sa_1, sb_1;
  for (genvar c = 0; c < 3; c++) begin : gen_mag
    logic signed [OpBits-1:0] av, bv;
    logic [AccBits-OpBits:0] unused_low;
    assign av = a_i[c*AccBits + AccBits - OpBits +: OpBits];
    assign bv = b_i[c*AccBits + AccBits - OpBits +: OpBits];
    if (AccBits > OpBits) begin : gen_unused
      assign unused_low = {1'b0, a_i[c*AccBits +: AccBits-OpBits] ^ b_i[c*AccBits +: AccBits-OpBits]};
    end else begin : gen_none
      assign unused_low = '0;
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        ma_1[c] <= av[OpBits-1] ? OpBits'(-av) : OpBits'(av);
        mb_1[c] <= bv[OpBits-1] ? OpBits'(-bv) : OpBits'(bv);
        s_1[c]  <= av[OpBits-1] ^ bv[OpBits-1];
        sa_1[c] <= av[OpBits-1];
        sb_1[c] <= bv[OpBits-1];
      end
    end
  end

  // ---- products ----
  logic [PBits-1:0] pd [3], pa [3], pb [3];
  for (genvar c = 0; c < 3; c++) begin : gen_mul
    phong_mul #(.ABits (OpBits), .BBits (OpBits), .TileBits (MulTileBits)) u_mul_ab (
      .clk_i (clk_i), .en_i (en_i), .a_i (ma_1[c]), .b_i (mb_1[c]), .p_o (pd[c]));
    phong_mul #(.ABits (OpBits), .BBits (OpBits), .TileBits (MulTileBits)) u_mul_aa (
      .clk_i (clk_i), .en_i (en_i), .a_i (ma_1[c]), .b_i (ma_1[c]), .p_o (pa[c]));
    phong_mul #(.ABits (OpBits), .BBits (OpBits), .TileBits (MulTileBits)) u_mul_bb (
      .clk_i (clk_i), .en_i (en_i), .a_i (mb_1[c]), .b_i (mb_1[c]), .p_o (pb[c]));
  end
  logic [2:0] s_m;
  specular_delay #(.Width (3), .Depth (MulDepth), .Reset (1'b0)) u_sign (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (s_1), .q_o (s_m));

  // ---- sums ----
  logic signed [DBits-1:0] q_3 [3];
  logic [PBits-1:0]        na_3, nb_3, pa2_3, pb2_3;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int c = 0; c < 3; c++) begin
        q_3[c] <= s_m[c] ? -(DBits'(pd[c])) : DBits'(pd[c]);
      end
      na_3  <= pa[0] + pa[1];
      nb_3  <= pb[0] + pb[1];
      pa2_3 <= pa[2];
      pb2_3 <= pb[2];
    end
  end

  logic signed [DBits-1:0] d_4, q2_4;
  logic [PBits-1:0]        na_4, nb_4;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_4  <= q_3[0] + q_3[1];
      q2_4 <= q_3[2];
      na_4 <= na_3 + pa2_3;
      nb_4 <= nb_3 + pb2_3;
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_o  <= d_4 + q2_4;
      na_o <= na_4;
      nb_o <= nb_4;
    end
  end

  // ---- u = a x b (Cross): u_c = a_i b_j - a_j b_i, (i, j) = (c+1, c+2) mod 3 ----
  localparam int UBits = 2 * OpBits + 1;
  if (Cross) begin : gen_cross
    logic [PBits-1:0] pp [3], pm [3];
    logic [2:0]       sp_m, sm_m;
    for (genvar c = 0; c < 3; c++) begin : gen_cmul
      localparam int I = (c + 1) % 3;
      localparam int J = (c + 2) % 3;
      phong_mul #(.ABits (OpBits), .BBits (OpBits), .TileBits (MulTileBits)) u_mul_p (
        .clk_i (clk_i), .en_i (en_i), .a_i (ma_1[I]), .b_i (mb_1[J]), .p_o (pp[c]));
      phong_mul #(.ABits (OpBits), .BBits (OpBits), .TileBits (MulTileBits)) u_mul_m (
        .clk_i (clk_i), .en_i (en_i), .a_i (ma_1[J]), .b_i (mb_1[I]), .p_o (pm[c]));
      specular_delay #(.Width (2), .Depth (MulDepth), .Reset (1'b0)) u_csign (
        .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({sa_1[I] ^ sb_1[J], sa_1[J] ^ sb_1[I]}),
        .q_o ({sp_m[c], sm_m[c]}));
    end
    logic signed [UBits-1:0] up_3 [3], um_3 [3], u_4 [3];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        for (int c = 0; c < 3; c++) begin
          up_3[c] <= sp_m[c] ? -(UBits'(pp[c])) : UBits'(pp[c]);
          um_3[c] <= sm_m[c] ? UBits'(pm[c]) : -(UBits'(pm[c]));
          u_4[c]  <= up_3[c] + um_3[c];
          u_o[c*UBits +: UBits] <= u_4[c];
        end
      end
    end
  end else begin : gen_no_cross
    logic unused_signs;
    assign unused_signs = ^{sa_1, sb_1};
    assign u_o = '0;
  end

endmodule
