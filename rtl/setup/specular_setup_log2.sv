// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_log2: log2 of a positive Q44 value (UnitFrac), Q30 (LogFrac), pipelined, one
// value per clock (docs/setup_hw.md#the-datapath, step 7; the golden model is
// host::fixed::log2_unit in model/host/setup_fixed.hpp). a = 2^(p-44) mant, mant in [1, 2); a 1024-word table pair
// gives a 12-bit reciprocal r_i of the interval of mant and -log2 r_i; e = mant r_i - 1,
// |e| < 2^-10, and log2(1 + e) = e (L1 + e (L2 + e L3)).
//
//   stage 1  lz, the zeros above the leading one (specular_setup_prio)
//   stage 2  mant, a shifted left by lz, and p - 44; both ROMs are read
//   stage 3  e = mant r_i - 1             stages 4, 5: the Horner steps
//   stage 6  (p - 44) + (-log2 r_i) + e (...)
// Each stage holds one carry chain at most (docs/setup_hw.md#the-rtl): a rounding and
// an added constant or integer part are one addend. Stages:
// specular_setup_pkg::LogStages. A non-positive a gives a defined, meaningless value (the
// setup does not use it). en_i freezes every stage. No reset.

`include "specular_assert.svh"

module specular_setup_log2 #(
  // The argument's width: the setup's A^2 in Q52, read as Q44 (< 8) as host::fixed::log2_unit
  // reads any int64.
  parameter int AmpW     = specular_setup_pkg::AmpW,
  parameter LogRecipFile = "roms/setup/log_recip.hex",
  parameter LogValueFile = "roms/setup/log_value.hex",
  // The setup's folding (specular_setup SetupII > 1: en_i once per slot of SetupII
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
  localparam int UnitFrac  = specular_setup_pkg::LogUnitFrac;
  localparam int LogFrac   = specular_setup_pkg::LogFrac;
  localparam int AddrBits  = specular_setup_pkg::LogAddrBits;
  localparam int RecipFrac = specular_setup_pkg::LogRecipFrac;
  localparam int Stages    = 6;
  localparam int EW        = LogFrac - AddrBits + 2;  // e: |e| < 2^-10, Q30
  localparam int TW        = LogFrac + 2;             // the Horner terms: |t| < 2

  if (AmpW < UnitFrac + 3) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_log2: AmpW must be at least UnitFrac + 3")
  end
  if (Stages != specular_setup_pkg::LogStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_log2: specular_setup_pkg::LogStages disagrees with the stages built here")
  end

  localparam int PTop      = AmpW - 2 - UnitFrac;  // p - 44 for lz = 0
  localparam int ES        = UnitFrac + RecipFrac - LogFrac;  // e's rounding shift
  // Each step's rounding and added constant, one addend (specular_setup_pkg::round_addend).
  localparam logic signed [63:0] AddE  = specular_setup_pkg::round_addend(-(64'sd1 <<< (UnitFrac + RecipFrac - ES)), ES);
  localparam logic signed [63:0] AddL2 = specular_setup_pkg::round_addend(specular_setup_pkg::L2, LogFrac);
  localparam logic signed [63:0] AddL1 = specular_setup_pkg::round_addend(specular_setup_pkg::L1, LogFrac);

  // Stage 1: the left shift lz that puts the leading one at bit AmpW - 2 (specular_setup_prio:
  // log2 depth, where a priority loop is a chain as long as a) and a != 0. Stage 2: mant is
  // the top UnitFrac + 1 bits below the sign there (the bits shifted out at the bottom
  // truncated, as host::fixed::log2_unit's right shift), and p - 44 = AmpW - 2 - 44 - lz, or
  // -45 for a = 0.
  localparam int PL = $clog2(AmpW - 1);  // specular_setup_prio's count
  logic [PL-1:0] lz_d;
  logic          nz_d;
  specular_setup_prio #(.W(AmpW - 1), .FromTop(1'b1)) u_lead (
    .a_i (a_i[AmpW-2:0]), .any_o (nz_d), .value_o (lz_d));
  logic [AmpW-2:0]      a_q;
  logic [PL-1:0]        lz_q;
  logic                 nz_q;
  logic [AmpW-2:0]      a_norm;
  logic [UnitFrac:0]    mant_d;  // [2^44, 2^45)
  assign a_norm = a_q << lz_q;
  assign mant_d = a_norm[AmpW-2 -: UnitFrac + 1];
  logic signed [31:0] p_rel;  // p - 44
  assign p_rel = nz_q ? 32'(PTop) - 32'(lz_q) : -32'(UnitFrac + 1);
  logic unused_norm;  // below mant: truncated; the sign (a > 0)
  assign unused_norm = ^{a_norm[AmpW-3-UnitFrac:0], a_i[AmpW-1]};
  logic [AddrBits-1:0] idx, idx_rd;
  assign idx = mant_d[UnitFrac-1 -: AddrBits];
  logic [RecipFrac-1:0] recip, recip_rd;   // r_i < 2^12
  logic                 recip_en;
  if (SetupII > 1) begin : gen_idx_reg
    // Folded, the stage's registers hold for the slot: the address is registered on every
    // clock, so the block RAM's address input ends a route from a flip-flop, not the
    // normalizing shift. r_i is read on every clock and its stage register is in the fabric,
    // loaded on the advance from the RAM's output (valid from clock 2 of the slot): it is a
    // shared unit's operand, and the RAM's 5.61 ns clock-to-output ended in the unit's tile
    // multiplexer (docs/setup_hw.md#the-folded-setup).
    always_ff @(posedge clk_i) idx_rd <= idx;
    always_ff @(posedge clk_i) begin
      if (en_i) recip <= recip_rd;
    end
    assign recip_en = 1'b1;
  end else begin : gen_idx_wire
    assign idx_rd   = idx;
    assign recip    = recip_rd;
    assign recip_en = en_i;
  end
  logic [LogFrac:0]     value;   // -log2 r_i in [0, 1], Q30
  specular_rom #(.Width(RecipFrac), .AddrBits(AddrBits), .File(LogRecipFile)) u_recip_rom (
    .clk_i (clk_i), .en_i (recip_en), .addr_i (idx_rd), .data_o (recip_rd)
  );
  specular_rom #(.Width(LogFrac + 1), .AddrBits(AddrBits), .File(LogValueFile)) u_value_rom (
    .clk_i (clk_i), .en_i (en_i), .addr_i (idx_rd), .data_o (value)
  );

  logic [UnitFrac:0]   mant_q;
  logic signed [EW-1:0] e_q, e_q5, e_q6;  // e, then beside the Horner steps
  logic signed [TW-1:0] t4_q, t5_q;
  logic signed [LogW-1:0] base_q [3:5];   // (p - 44) 2^30 + (-log2 r_i), beside them too
  logic signed [LogW-1:0] p_q;
  // The four products: mant recip, e L3, e t4, e t5.
  logic signed [63:0] pm [4];
  if (SetupII > 1) begin : gen_fold
    localparam int FA = 35, FB = 52, FN = 4;  // recip or e (A) times mant, L3 or t (B): 2 x 3 tiles
    if (RecipFrac + 1 > FA || EW > FA || UnitFrac + 2 > FB || TW > FB) begin : gen_fold_width_check
      `SPEC_PARAM_ERROR("specular_setup_log2: the folded unit's lanes are too narrow")
    end
    logic [FN*FA-1:0]      f_a;
    logic [FN*FB-1:0]      f_b;
    logic [FN*(FA+FB)-1:0] f_p, f_pc;
    assign f_a = {FA'(e_q6), FA'(e_q5), FA'(e_q), FA'({1'b0, recip})};
    assign f_b = {FB'(t5_q), FB'(t4_q), FB'(specular_setup_pkg::L3), FB'({1'b0, mant_q})};
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
    assign pm[2] = specular_setup_pkg::mul64(64'(e_q5), 64'(t4_q));
    assign pm[3] = specular_setup_pkg::mul64(64'(e_q6), 64'(t5_q));
  end
  // Stage 6's addend: the integer part and the rounding half side by side, 2^30 base + 2^29.
  logic signed [LogW+LogFrac-1:0] last_sum;
  assign last_sum = (LogW + LogFrac)'(pm[3]) + {base_q[5], 1'b1, (LogFrac - 1)'(0)};
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      a_q    <= a_i[AmpW-2:0];
      lz_q   <= nz_d ? lz_d : '0;
      nz_q   <= nz_d;
      // stage 2
      mant_q <= mant_d;
      p_q    <= LogW'(p_rel) <<< LogFrac;
      // stage 3
      e_q       <= EW'((pm[0] + AddE) >>> ES);
      base_q[3] <= p_q + LogW'(value);
      // stages 4 and 5
      t4_q      <= TW'((pm[1] + AddL2) >>> LogFrac);
      base_q[4] <= base_q[3];
      t5_q      <= TW'((pm[2] + AddL1) >>> LogFrac);
      base_q[5] <= base_q[4];
      e_q5      <= e_q;
      e_q6      <= e_q5;
      // stage 6
      log2_o    <= LogW'(last_sum >>> LogFrac);
    end
  end
endmodule
