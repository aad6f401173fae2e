// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// The normalization of phong_stream (docs/phong_hw.md#design): c = d / sqrt(na nb) with
// CosFrac fraction bits, clamped to 1, by mantissas, a 1/sqrt ROM and Newton-Raphson steps.
// Bit-exact contract (every shift and truncation): model/device/phong_model.hpp.
// phong_pkg::norm_stages(NormBits, Newton) stages:
//   1        ea, eb: the even exponents of na, nb (priority encoders); d > 0
//   2        ma, mb (shifts); ea/2 + eb/2
//   3 ..     ma * mb (phong_mul); dn0 = d 2^(CosFrac - ea/2 - eb/2) (shift) beside it
//   +1       em = (ma mb >= 4); mm; the ROM address; dn = dn0 >> em
//   +1       the rsqrt ROM read: y0
//   Newton   per step: y*y, mm*t, 3 - u, y*v (phong_mul, one subtraction)
//   ..       dn * y (phong_mul)
//   last     the clamp to 1 and the zero flag (d <= 0 or c = 0)

`include "specular_assert.svh"

module phong_norm #(
  parameter int OpBits        = 19,
  parameter int NormBits      = 24,
  parameter int RsqrtAddrBits = 6,
  parameter int Newton        = 2,
  parameter int CosFrac       = 23,
  parameter     RsqrtRomFile  = "",
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits   = 0
) (
  input  logic                       clk_i,
  input  logic                       en_i,
  input  logic signed [2*OpBits+1:0] d_i,
  input  logic [2*OpBits-1:0]        na_i,
  input  logic [2*OpBits-1:0]        nb_i,
  output logic [CosFrac:0]           c_o,
  output logic                       zero_o
);

  localparam int PBits   = 2 * OpBits;
  localparam int DBits   = 2 * OpBits + 2;
  localparam int MFrac   = NormBits - 2;
  localparam int EBits   = $clog2(PBits + 1);
  localparam int DnBits  = CosFrac + 2;
  localparam int MulN    = phong_pkg::mul_stages(NormBits);
  localparam int MulV    = phong_pkg::mul_stages(NormBits + 2);
  localparam int MulC    = phong_pkg::mul_stages(NormBits);
  localparam int StepLen = phong_pkg::newton_stages(NormBits);
  localparam int Depth   = phong_pkg::norm_stages(NormBits, Newton);

  if (PBits > 64 || RsqrtAddrBits < 3 || RsqrtAddrBits > NormBits || Newton < 0 || Newton > 2 ||
      Depth != 2 + MulN + 2 + Newton * StepLen + MulC + 1 || StepLen != 2 * MulN + 1 + MulV) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_norm: 2 OpBits <= 64, 3 <= RsqrtAddrBits <= NormBits, Newton in 0..2; phong_pkg disagrees")
  end

  // ---- stage 1: exponents ----

  logic [PBits-1:0]        na_1, nb_1;
  logic [EBits-1:0]        ea_1, eb_1;
  logic signed [DBits-1:0] d_1;
  logic                    dpos_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      na_1   <= na_i;
      nb_1   <= nb_i;
      ea_1   <= EBits'(phong_pkg::even_exp(64'(na_i)));
      eb_1   <= EBits'(phong_pkg::even_exp(64'(nb_i)));
      d_1    <= d_i;
      dpos_1 <= !d_i[DBits-1] && d_i != '0;
    end
  end

  // ---- stage 2: mantissas, the exponent of the product ----
  logic [NormBits-1:0]  ma_2, mb_2;
  logic [EBits:0]       dk_2;
  logic [DBits-1:0]     d_2;
  logic                 dpos_2;
  logic [PBits+MFrac-1:0] sa, sb;
  assign sa = {na_1, MFrac'(0)} >> ea_1;
  assign sb = {nb_1, MFrac'(0)} >> eb_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ma_2   <= sa[NormBits-1:0];
      mb_2   <= sb[NormBits-1:0];
      dk_2   <= ((EBits + 1)'(ea_1) >> 1) + ((EBits + 1)'(eb_1) >> 1);
      d_2    <= d_1;
      dpos_2 <= dpos_1;
    end
  end
  logic [PBits+MFrac-1:NormBits] unused_sab;
  assign unused_sab = sa[PBits+MFrac-1:NormBits] ^ sb[PBits+MFrac-1:NormBits];

  // ---- ma * mb, dn0 beside ----
  logic [2*NormBits-1:0] m_p;
  phong_mul #(.ABits (NormBits), .BBits (NormBits), .TileBits (MulTileBits)) u_mul_m (
    .clk_i (clk_i), .en_i (en_i), .a_i (ma_2), .b_i (mb_2), .p_o (m_p));

  logic [DBits+CosFrac-1:0] sd;
  logic [DnBits-1:0]        dn0_3, dn0_m;
  logic                     dpos_3, dpos_m;
  assign sd = {d_2, CosFrac'(0)} >> dk_2;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      dn0_3  <= sd[DnBits-1:0];
      dpos_3 <= dpos_2;
    end
  end
  logic [DBits+CosFrac-1:DnBits] unused_sd;
  assign unused_sd = sd[DBits+CosFrac-1:DnBits];
  specular_delay #(.Width (DnBits + 1), .Depth (MulN - 1), .Reset (1'b0)) u_dn0 (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({dn0_3, dpos_3}), .q_o ({dn0_m, dpos_m}));

  // ---- em, mm, ROM address, dn ----
  logic                     em;
  logic [NormBits-1:0]      mm_c;
  logic [NormBits-1:0]      mm_a;
  logic [RsqrtAddrBits-1:0] idx_a;
  logic [DnBits-1:0]        dn_a;
  logic                     dpos_a;
  assign em   = |m_p[2*NormBits-1:2*NormBits-2];
  assign mm_c = em ? m_p[MFrac+2 +: NormBits] : m_p[MFrac +: NormBits];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mm_a   <= mm_c;
      // mm's top RsqrtAddrBits bits minus 2^(RsqrtAddrBits-2): the top two bits (01, 10, 11) less one.
      idx_a  <= {mm_c[NormBits-1:NormBits-2] - 2'd1, mm_c[NormBits-3 -: RsqrtAddrBits-2]};
      dn_a   <= em ? dn0_m >> 1 : dn0_m;
      dpos_a <= dpos_m;
    end
  end
  logic unused_m;
  assign unused_m = ^m_p[MFrac-1:0];

  // ---- the rsqrt ROM ----
  logic [NormBits-1:0] y_s   [Newton+1];
  logic [NormBits-1:0] mm_s  [Newton+1];
  logic [DnBits-1:0]   dn_s  [Newton+1];
  logic                dpos_s [Newton+1];
  specular_rom #(
    .Width    (NormBits),
    .AddrBits (RsqrtAddrBits),
    .Depth    (3 << (RsqrtAddrBits - 2)),
    .File     (RsqrtRomFile)
  ) u_rsqrt_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (idx_a),
    .data_o (y_s[0])
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mm_s[0]   <= mm_a;
      dn_s[0]   <= dn_a;
      dpos_s[0] <= dpos_a;
    end
  end

  // ---- Newton steps: y = y (3 - mm y^2) / 2 ----
  for (genvar s = 0; s < Newton; s++) begin : gen_newton
    logic [2*NormBits-1:0] sq_p, u_p;
    logic [2*NormBits+1:0] y_p;
    logic [NormBits-1:0]   mm_d, y_d;
    logic [NormBits+1:0]   v_q;
    phong_mul #(.ABits (NormBits), .BBits (NormBits), .TileBits (MulTileBits)) u_mul_sq (
      .clk_i (clk_i), .en_i (en_i), .a_i (y_s[s]), .b_i (y_s[s]), .p_o (sq_p));
    specular_delay #(.Width (NormBits), .Depth (MulN), .Reset (1'b0)) u_mm_d (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (mm_s[s]), .q_o (mm_d));
    phong_mul #(.ABits (NormBits), .BBits (NormBits), .TileBits (MulTileBits)) u_mul_u (
      .clk_i (clk_i), .en_i (en_i), .a_i (mm_d), .b_i (sq_p[NormBits +: NormBits]), .p_o (u_p));
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        v_q <= ((NormBits + 2)'(3) << NormBits) - u_p[MFrac +: NormBits + 2];
      end
    end
    specular_delay #(.Width (NormBits), .Depth (2 * MulN + 1), .Reset (1'b0)) u_y_d (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (y_s[s]), .q_o (y_d));
    phong_mul #(.ABits (NormBits), .BBits (NormBits + 2), .TileBits (MulTileBits)) u_mul_y (
      .clk_i (clk_i), .en_i (en_i), .a_i (y_d), .b_i (v_q), .p_o (y_p));
    assign y_s[s+1] = y_p[NormBits+1 +: NormBits];
    specular_delay #(.Width (NormBits + DnBits + 1), .Depth (StepLen), .Reset (1'b0)) u_side (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({mm_s[s], dn_s[s], dpos_s[s]}),
      .q_o ({mm_s[s+1], dn_s[s+1], dpos_s[s+1]}));
    logic unused_p;
    assign unused_p = ^{sq_p[NormBits-1:0], u_p[MFrac-1:0], y_p[NormBits:0], y_p[2*NormBits+1]};
  end

  // ---- c = dn * y ----
  logic [DnBits+NormBits-1:0] c_p;
  logic                       dpos_c;
  phong_mul #(.ABits (DnBits), .BBits (NormBits), .TileBits (MulTileBits)) u_mul_c (
    .clk_i (clk_i), .en_i (en_i), .a_i (dn_s[Newton]), .b_i (y_s[Newton]), .p_o (c_p));
  specular_delay #(.Width (1), .Depth (MulC), .Reset (1'b0)) u_dpos_c (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (dpos_s[Newton]), .q_o (dpos_c));
  logic unused_mm;
  assign unused_mm = ^{mm_s[Newton], c_p[NormBits-1:0]};

  // ---- clamp ----
  logic [DnBits-1:0] c_raw;
  assign c_raw = c_p[NormBits +: DnBits];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      c_o    <= (c_raw[DnBits-1:CosFrac] != '0) ? (CosFrac + 1)'(1) << CosFrac : c_raw[CosFrac:0];
      zero_o <= !dpos_c || c_raw == '0;
    end
  end

endmodule
