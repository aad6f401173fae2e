// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_log2: log2 of a positive Q44 value (UnitFrac), Q30 (LogFrac), pipelined, one
// value per clock (docs/setup_hw.md#datapath, step 7; the golden model is
// host::fixed::log2_unit in model/host/setup_fixed.hpp). a = 2^(p-44) mant, mant in [1, 2); a 1024-word table pair
// gives a 12-bit reciprocal r_i of the interval of mant and -log2 r_i; e = mant r_i - 1,
// |e| < 2^-10, and log2(1 + e) = e (L1 + e (L2 + e L3)).
//
//   stage 1  p and mant (leading-one position); both ROMs are read
//   stage 2  e = mant r_i - 1             stages 3, 4: the Horner steps
//   stage 5  (p - 44) + (-log2 r_i) + e (...)
// Stages: specular_setup_pkg::LogStages. A non-positive a gives a defined, meaningless
// value (the setup does not use it). en_i freezes every stage. No reset.

`include "specular_assert.svh"

module specular_setup_log2 #(
  // The argument's width: specular_setup's A (Q44 < 8); the lean setup's A^2 in Q52, read as
  // Q44 as host::fixed::log2_unit reads any int64.
  parameter int AmpW     = specular_setup_pkg::AmpW,
  parameter LogRecipFile = "roms/setup/log_recip.hex",
  parameter LogValueFile = "roms/setup/log_value.hex",
  // The lean setup's folding (specular_setup_lean SetupII > 1: en_i once per slot of SetupII
  // clocks): the four products share a specular_setup_fmul, each read before its unit's
  // register and rounded in its own stage as here. 1: the inline products.
  parameter int SetupII  = 1,
  parameter int TileBits = 18
) (
  input  logic                                       clk_i,
  input  logic                                       en_i,
  input  logic signed [AmpW-1:0]                     a_i,
  output logic signed [specular_setup_pkg::LogW-1:0] log2_o
);

  localparam int LogW      = specular_setup_pkg::LogW;
  localparam int UnitFrac  = specular_setup_pkg::UnitFrac;
  localparam int LogFrac   = specular_setup_pkg::LogFrac;
  localparam int AddrBits  = specular_setup_pkg::LogAddrBits;
  localparam int RecipFrac = specular_setup_pkg::LogRecipFrac;
  localparam int Stages    = 5;
  localparam int EW        = LogFrac - AddrBits + 2;  // e: |e| < 2^-10, Q30
  localparam int TW        = LogFrac + 2;             // the Horner terms: |t| < 2

  if (Stages != specular_setup_pkg::LogStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_log2: specular_setup_pkg::LogStages disagrees with the stages built here")
  end

  // Stage 1.
  logic signed [31:0]   p_d;
  logic [UnitFrac:0]    mant_d;  // [2^44, 2^45)
  always_comb begin
    p_d = -1;
    for (int b = 0; b < AmpW - 1; b++) begin
      if (a_i[b]) p_d = b;
    end
    if (p_d <= UnitFrac) begin
      mant_d = (UnitFrac + 1)'(a_i <<< (UnitFrac - p_d));
    end else begin
      mant_d = (UnitFrac + 1)'(a_i >>> (p_d - UnitFrac));
    end
  end
  logic signed [31:0] p_rel;
  assign p_rel = p_d - 32'(UnitFrac);
  logic [AddrBits-1:0] idx;
  assign idx = mant_d[UnitFrac-1 -: AddrBits];
  logic [RecipFrac-1:0] recip;   // r_i < 2^12
  logic [LogFrac:0]     value;   // -log2 r_i in [0, 1], Q30
  specular_rom #(.Width(RecipFrac), .AddrBits(AddrBits), .File(LogRecipFile)) u_recip_rom (
    .clk_i (clk_i), .en_i (en_i), .addr_i (idx), .data_o (recip)
  );
  specular_rom #(.Width(LogFrac + 1), .AddrBits(AddrBits), .File(LogValueFile)) u_value_rom (
    .clk_i (clk_i), .en_i (en_i), .addr_i (idx), .data_o (value)
  );

  logic [UnitFrac:0]   mant_q;
  logic signed [EW-1:0] e_q, e_q4, e_q5;  // e, then beside the Horner steps
  logic signed [TW-1:0] t3_q, t4_q;
  logic signed [LogW-1:0] base_q [2:4];   // (p - 44) 2^30 + (-log2 r_i), beside them too
  logic signed [LogW-1:0] p_q;
  // The four products: mant recip, e L3, e t3, e t4.
  logic signed [63:0] pm [4];
  if (SetupII > 1) begin : gen_fold
    localparam int FA = 35, FB = 52, FN = 4;  // recip or e (A) times mant, L3 or t (B): 2 x 3 tiles
    if (RecipFrac + 1 > FA || EW > FA || UnitFrac + 2 > FB || TW > FB) begin : gen_fold_width_check
      `SPEC_PARAM_ERROR("specular_setup_log2: the folded unit's lanes are too narrow")
    end
    logic [FN*FA-1:0]      f_a;
    logic [FN*FB-1:0]      f_b;
    logic [FN*(FA+FB)-1:0] f_p, f_pc;
    assign f_a = {FA'(e_q5), FA'(e_q4), FA'(e_q), FA'({1'b0, recip})};
    assign f_b = {FB'(t4_q), FB'(t3_q), FB'(specular_setup_pkg::L3), FB'({1'b0, mant_q})};
    specular_setup_fmul #(.N(FN), .ABits(FA), .BBits(FB), .TileBits(TileBits), .SetupII(SetupII)) u_fmul (
      .clk_i (clk_i), .en_i (en_i), .a_i (f_a), .b_i (f_b), .p_o (f_p), .pc_o (f_pc));
    for (genvar i = 0; i < FN; i++) begin : gen_lane
      assign pm[i] = f_pc[i*(FA+FB) +: 64];
    end
    logic unused_fold;
    assign unused_fold = ^{f_p, f_pc};  // each lane's low 64 bits: mul64's
  end else begin : gen_inline
    assign pm[0] = specular_setup_pkg::mul64(64'(mant_q), 64'(recip));
    assign pm[1] = specular_setup_pkg::mul64(64'(e_q), specular_setup_pkg::L3);
    assign pm[2] = specular_setup_pkg::mul64(64'(e_q4), 64'(t3_q));
    assign pm[3] = specular_setup_pkg::mul64(64'(e_q5), 64'(t4_q));
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      mant_q <= mant_d;
      p_q    <= LogW'(p_rel) <<< LogFrac;
      // stage 2
      e_q       <= EW'(specular_setup_pkg::rshift_round64(pm[0] - (64'sd1 <<< (UnitFrac + RecipFrac)),
                                                      UnitFrac + RecipFrac - LogFrac));
      base_q[2] <= p_q + LogW'(value);
      // stages 3 and 4
      t3_q      <= TW'(specular_setup_pkg::L2 +
                   specular_setup_pkg::rshift_round64(pm[1], LogFrac));
      base_q[3] <= base_q[2];
      t4_q      <= TW'(specular_setup_pkg::L1 +
                   specular_setup_pkg::rshift_round64(pm[2], LogFrac));
      base_q[4] <= base_q[3];
      e_q4      <= e_q;
      e_q5      <= e_q4;
      // stage 5
      log2_o    <= base_q[4] + LogW'(specular_setup_pkg::rshift_round64(pm[3], LogFrac));
    end
  end
endmodule
