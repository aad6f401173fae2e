// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Multiplier 11 of patent UA 71489: zeta = a(n) * |psi|, turned into the ROM 12 address.
// Bit-exact contract (model/device/device_model.hpp):
//   |psi|   one's complement of register 8 (psi >= 0 ? psi : ~psi, one code below |psi| for
//           negative psi): cos is even, and no carry chain is spent on the negation
//   far     |psi| >= pi/2 exactly (the comparison allows for the one's complement): N.H < 0
//           there and the reference is 0 (an erratum: where a(n) < 1 the lobe of
//           cos^k(a psi) would otherwise run past pi/2;
//           docs/device.md#errata-of-the-patent-and-how-each-is-resolved)
//   psi_t   |psi| truncated to 1 integer and PsiMulFrac fraction bits (|psi| < pi/2 < 2)
//   zeta    coef * psi_t, coef = a(n) * 2/pi from ROM 9 (CoefFrac fraction bits), so zeta is
//           in quarter turns: zeta >= 1 means a*|psi| >= pi/2, where ROM 12 has no entry
//   interpolated ROM 12 (CosInterp = 1): addr = the CosAddrBits bits of zeta below the binary
//           point, frac = the next CosFracBits bits (the rest truncated); zero when zeta >= 1
//   direct ROM 12 (CosInterp = 0, the patent): addr = round-half-up(zeta * 2^CosAddrBits),
//           zero when that reaches 2^CosAddrBits
//   zero    far, or past a quarter turn, or n invalid (decoder 10)
// Pipeline, every register enabled by en_i (stall): stage 1 |psi| and the coefficient;
// then the radix-4 multiplier tree (specular_pipe_mul) with the pi/2 test (in its first two
// stages) and n_valid beside it; then the address register and
// specular_pkg::Mul11RetimeStages retiming registers: specular_pkg::angle_mul_stages clocks
// from psi_i to addr_o / frac_o / zero_o (docs/pipeline.md#stage-counts).

`include "specular_assert.svh"

module specular_angle_mul #(
  parameter int AccBits     = 44,
  parameter int AngleFrac   = 28,
  parameter int CoefBits    = 21,
  parameter int CoefFrac    = 18,
  parameter int PsiMulFrac  = 20,
  parameter bit CosInterp   = 1'b1,
  parameter int CosAddrBits = 8,
  parameter int CosFracBits = 12,
  parameter int MulTileBits = 0    // specular_pipe_mul's TileBits: 0 LUT tree, 16 / 18 DSP tiles
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          en_i,      // pipeline advance (clock enable)
  input  logic signed [AccBits-1:0]     psi_i,     // register 8
  input  logic        [CoefBits-1:0]    coef_i,    // ROM 9, this pixel's span
  input  logic                          n_valid_i, // decoder 10, this pixel's span
  output logic        [CosAddrBits-1:0] addr_o,    // ROM 12 address within the bank
  output logic        [CosFracBits-1:0] frac_o,    // interpolation weight (0 when direct)
  output logic                          zero_o     // this pixel is 0
);

  localparam int PsiTBits  = 1 + PsiMulFrac;
  // Radix-4 tree over the bits of |psi|_t (specular_pipe_mul); the block's registers around
  // it are those specular_pkg::angle_mul_stages counts (docs/pipeline.md#stage-counts).
  localparam int MulStages = specular_pkg::pipe_mul_stages(PsiTBits);
  localparam int RetimeStages = specular_pkg::Mul11RetimeStages;
  localparam int ZetaBits  = CoefBits + PsiTBits;
  localparam int ZetaFrac  = CoefFrac + PsiMulFrac;
  localparam int DropBits  = ZetaFrac - CosAddrBits;    // bits below the ROM address
  // ceil(pi/2 * 2^AngleFrac) from pi/2 * 2^62 (pi is irrational, so floor + 1 is the ceiling).
  localparam logic [63:0] PiHalfQ62 = 64'h6487_ED51_10B4_611A;
  localparam logic [AccBits-1:0] HalfPiCode = AccBits'((PiHalfQ62 >> (62 - AngleFrac)) + 64'd1);

  if (PsiMulFrac > AngleFrac) begin : gen_frac_check
    `SPEC_PARAM_ERROR("specular_angle_mul: PsiMulFrac must not exceed AngleFrac")
  end
  if (AngleFrac > 62 || AccBits < AngleFrac + 2) begin : gen_acc_check
    `SPEC_PARAM_ERROR("specular_angle_mul: AccBits must hold the sign and an integer bit, AngleFrac <= 62")
  end
  if (DropBits < 1) begin : gen_drop_check
    `SPEC_PARAM_ERROR("specular_angle_mul: CoefFrac + PsiMulFrac must exceed CosAddrBits")
  end
  if (specular_pkg::Mul11InStages != 1 || specular_pkg::Mul11OutStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_angle_mul: builds one register in front of the tree and one address register behind it (specular_pkg)")
  end
  if (RetimeStages < 0) begin : gen_retime_check
    `SPEC_PARAM_ERROR("specular_angle_mul: specular_pkg::Mul11RetimeStages must be >= 0")
  end
  if (MulStages < 2) begin : gen_stages_check
    `SPEC_PARAM_ERROR("specular_angle_mul: PsiMulFrac must be >= 2 (the pi/2 test needs two stages)")
  end
  if (CosInterp && DropBits < CosFracBits) begin : gen_interp_check
    `SPEC_PARAM_ERROR("specular_angle_mul: zeta has too few fraction bits for CosAddrBits + CosFracBits")
  end

  // ---- Stage 1: one's complement magnitude, coefficient copy (off the ROM 9 output).
  logic [AccBits-1:0] ones_d, ones_q;
  logic               neg_q;
  logic [CoefBits-1:0] coef_q;
  logic [CoefBits+1:0] coef3_q;   // 3 * coef for the radix-4 digits of the tree
  assign ones_d = psi_i ^ {AccBits{psi_i[AccBits-1]}};

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ones_q  <= ones_d;
      neg_q   <= psi_i[AccBits-1];
      coef_q  <= coef_i;
      coef3_q <= (CoefBits + 2)'(coef_i) + ((CoefBits + 2)'(coef_i) << 1);
    end
  end

  // ---- Stages 2 .. 1 + MulStages: the multiplier tree; far and n_valid beside it.
  // |psi| >= pi/2 is split over two stages so that no clock holds more than a half-width
  // comparison: stage 2 compares the high and low halves with the constant (H, or H - 1 for
  // negative psi, whose one's complement is one code low; H - 1 has the same high half
  // because the low half of H is not 0), stage 3 combines them.
  localparam int LoBits = AccBits / 2;
  localparam logic [AccBits-1:0] HalfPiNeg = HalfPiCode - AccBits'(1);
  if (HalfPiCode[LoBits-1:0] == '0) begin : gen_half_check
    `SPEC_PARAM_ERROR("specular_angle_mul: the low half of ceil(pi/2 * 2^AngleFrac) must not be 0")
  end
  logic gt_hi_q, eq_hi_q, ge_lo_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      gt_hi_q <= ones_q[AccBits-1:LoBits] > HalfPiCode[AccBits-1:LoBits];
      eq_hi_q <= ones_q[AccBits-1:LoBits] == HalfPiCode[AccBits-1:LoBits];
      ge_lo_q <= neg_q ? (ones_q[LoBits-1:0] >= HalfPiNeg[LoBits-1:0])
                       : (ones_q[LoBits-1:0] >= HalfPiCode[LoBits-1:0]);
    end
  end
  logic far;
  assign far = gt_hi_q | (eq_hi_q & ge_lo_q);

  logic [PsiTBits-1:0] psi_t;
  assign psi_t = ones_q[AngleFrac -: PsiTBits];

  logic [ZetaBits-1:0] zeta;
  specular_pipe_mul #(
    .ABits    (CoefBits),
    .BBits    (PsiTBits),
    .TileBits (MulTileBits)
  ) u_tree (
    .clk_i (clk_i),
    .en_i  (en_i),
    .a_i   (coef_q),
    .a3_i  (coef3_q),
    .b_i   (psi_t),
    .p_o   (zeta)
  );

  logic far_m, n_valid_m;
  specular_delay #(.Width (1), .Depth (1 + MulStages)) u_nvalid_m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .d_i (n_valid_i), .q_o (n_valid_m));
  specular_delay #(.Width (1), .Depth (MulStages - 1)) u_far_m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .d_i (far), .q_o (far_m));

  // ---- Last stage: ROM 12 address, interpolation weight, zero flag.
  logic [CosAddrBits-1:0] addr_d, addr_q;
  logic [CosFracBits-1:0] frac_d, frac_q;
  logic                   past_quarter, zero_q;

  if (CosInterp) begin : gen_interp
    assign past_quarter = |zeta[ZetaBits-1:ZetaFrac];
    assign addr_d       = zeta[ZetaFrac-1 -: CosAddrBits];
    assign frac_d       = zeta[DropBits-1 -: CosFracBits];
    if (DropBits > CosFracBits) begin : gen_unused
      logic unused_zeta_lsbs;
      assign unused_zeta_lsbs = ^zeta[DropBits-CosFracBits-1:0];
    end
  end else begin : gen_direct
    localparam int AddrWBits = ZetaBits - DropBits + 1;
    logic [ZetaBits:0]    zeta_rnd;
    logic [AddrWBits-1:0] addr_w;
    assign zeta_rnd     = {1'b0, zeta} + ((ZetaBits + 1)'(1) << (DropBits - 1));  // round half up
    assign addr_w       = zeta_rnd[ZetaBits:DropBits];
    assign past_quarter = |addr_w[AddrWBits-1:CosAddrBits];
    assign addr_d       = addr_w[CosAddrBits-1:0];
    assign frac_d       = '0;
    logic unused_zeta_lsbs;
    assign unused_zeta_lsbs = ^zeta_rnd[DropBits-1:0];
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      addr_q <= addr_d;
      frac_q <= frac_d;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      zero_q <= 1'b0;
    end else if (en_i) begin
      zero_q <= far_m | past_quarter | ~n_valid_m;
    end
  end

  // Retiming registers behind the address register (specular_pkg::Mul11RetimeStages).
  specular_delay #(.Width (CosAddrBits + CosFracBits), .Depth (RetimeStages), .Reset (1'b0)) u_retime (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .d_i ({addr_q, frac_q}), .q_o ({addr_o, frac_o}));
  specular_delay #(.Width (1), .Depth (RetimeStages)) u_retime_zero (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .d_i (zero_q), .q_o (zero_o));

  // Bits of |psi| past pi/2 only matter through `far`; bits below the multiplier's
  // precision are deliberately dropped.
  logic unused_ones;
  if (AngleFrac > PsiMulFrac) begin : gen_unused_low
    assign unused_ones = ^ones_q[AngleFrac-PsiMulFrac-1:0];
  end else begin : gen_no_low
    assign unused_ones = 1'b0;
  end

  // Assertions (rtl/prim/specular_assert.svh): the advance and the zero flag are never X.
  // (Whether a stage holds a pixel is known only to the control unit: the address of a
  // bubble may be X, and the known checks of the pixels are further on.)
  `SPEC_ASSERT_KNOWN(EnKnown_A, en_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(ZeroKnown_A, zero_o, clk_i, rst_ni)

endmodule
