// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_exp2: C = scale 2^e, rounded to a code and saturated at the top of
// register 1, pipelined, one value per clock (docs/setup_hw.md#the-datapath, step 7; the
// golden model is host::fixed::scale_exp2 in model/host/setup_fixed.hpp). e is Q30;
// e = ei + f, ei = floor(e); a 1024-word table gives 2^(j/1024) for the top 10 bits j of f,
// and 2^g = 1 + g (E1 + g (E2 + g E3)) the rest g < 2^-10.
//
//   stage 1  ei, g; the ROM is read        stages 2, 3, 4: the Horner steps
//   stage 5  mant = 2^(j/1024) 2^g         stage 6: mant scale registered
//   stage 7  shifted by 29 - ei            stage 8: rounded (the last bit), saturated
// Each stage holds one carry chain at most (docs/setup_hw.md#the-rtl): a rounding and
// an added constant are one addend, and the shift is decoded from ei in stage 2, beside the
// Horner steps. Stages: specular_setup_pkg::ExpStages. en_i freezes
// every stage. No reset.

`include "specular_assert.svh"

module specular_setup_exp2 #(
  parameter int CBits   = 16,
  parameter     Exp2File = "roms/setup/exp2.hex",
  // The setup's folding (as specular_setup_log2's): the five products share a
  // specular_setup_fmul, the Horner steps' read before its register, mant scale after it
  // (stage 6). 1: the inline products.
  parameter int SetupII  = 1,
  parameter int TileBits = 18
) (
  input  logic               clk_i,
  input  logic               en_i,
  input  logic signed [specular_setup_pkg::ExpW-1:0] e_i,
  input  logic [CBits-1:0]   scale_i,
  output logic [CBits-1:0]   c_o,
  output logic               sat_o     // C was clamped to the top code
);

  localparam int LogFrac  = specular_setup_pkg::LogFrac;
  localparam int AddrBits = specular_setup_pkg::LogAddrBits;
  localparam int LoBits   = LogFrac - AddrBits;
  localparam int ExpW     = specular_setup_pkg::ExpW;
  localparam int EiW      = ExpW - LogFrac;  // the integer part ei
  localparam int TW       = LogFrac + 2;     // the Horner terms and the mantissa: |value| < 2
  localparam int Stages   = 8;
  localparam int MaxEi    = 16;              // above: every non-zero scale saturates C
  localparam int MinEi    = -(LogFrac + 1);  // below: C rounds to 0
  localparam int PW       = TW + CBits;      // mant scale: 0 <= value < 2^(LogFrac + 1 + CBits)
  localparam int ShW      = $clog2(LogFrac - MinEi);  // the shift LogFrac - 1 - ei, 13 .. 60
  localparam int VW       = PW - (LogFrac - 1 - MaxEi) + 1;  // the shifted product, the sign bit 0
  // Each Horner step's rounding and added constant, one addend (specular_setup_pkg::round_addend).
  localparam logic signed [63:0] AddE2  = specular_setup_pkg::round_addend(specular_setup_pkg::E2, LogFrac);
  localparam logic signed [63:0] AddE1  = specular_setup_pkg::round_addend(specular_setup_pkg::E1, LogFrac);
  localparam logic signed [63:0] AddOne = specular_setup_pkg::round_addend(64'sd1 <<< LogFrac, LogFrac);
  localparam logic signed [63:0] AddMant = specular_setup_pkg::round_addend(64'sd0, LogFrac);

  if (Stages != specular_setup_pkg::ExpStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_exp2: specular_setup_pkg::ExpStages disagrees with the stages built here")
  end
  // Above 2^16 every non-zero scale saturates (the exponent test of stage 2).
  if (CBits > 16) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_exp2: CBits must be at most 16")
  end

  // Stage 1.
  logic signed [EiW-1:0] ei_d;
  logic [LogFrac-1:0]    f_d;
  logic [AddrBits-1:0]   j_d;
  assign ei_d = EiW'(e_i >>> LogFrac);
  assign f_d  = e_i[LogFrac-1:0];  // e - ei 2^30, in [0, 2^30)
  assign j_d  = f_d[LogFrac-1 -: AddrBits];
  logic [LogFrac:0] pow_j;  // 2^(j/1024), Q30
  specular_rom #(.Width(LogFrac + 1), .AddrBits(AddrBits), .File(Exp2File)) u_exp2_rom (
    .clk_i (clk_i), .en_i (en_i), .addr_i (j_d), .data_o (pow_j)
  );

  logic [LoBits-1:0]     g_q [1:4];
  logic signed [EiW-1:0] ei_q;
  logic [CBits-1:0]      scale_q [1:6];
  logic [LogFrac:0]      pow_q [2:4];
  logic signed [TW-1:0]  t2_q, t3_q, p4_q, mant_q;
  // Stage 2 decodes ei: C is 0 (ei < MinEi or scale 0), saturated (ei > MaxEi), or the
  // product shifted right by LogFrac - 1 - ei and rounded by one more bit.
  logic [ShW-1:0] sh_q [2:7];
  logic           zero_q [2:7], big_q [2:7];
  logic [PW-1:0]  prod;      // stage 6: mant scale
  logic [VW-1:0]  shift_d, shift_q;   // stage 7
  // The five products: g E3, g t2, g t3, 2^(j/1024) p4, mant scale.
  logic signed [63:0] pm [4];
  if (SetupII > 1) begin : gen_fold
    localparam int FA = 35, FB = 35, FN = 5;  // 2 x 2 tiles
    if (LoBits + 1 > FA || LogFrac + 2 > FA || CBits + 1 > FA || TW > FB) begin : gen_fold_width_check
      `SPEC_PARAM_ERROR("specular_setup_exp2: the folded unit's lanes are too narrow")
    end
    logic [FN*FA-1:0]      f_a;
    logic [FN*FB-1:0]      f_b;
    logic [FN*(FA+FB)-1:0] f_p, f_pc;
    assign f_a = {FA'({1'b0, scale_q[5]}), FA'({1'b0, pow_q[4]}), FA'({1'b0, g_q[3]}), FA'({1'b0, g_q[2]}),
                  FA'({1'b0, g_q[1]})};
    assign f_b = {FB'(mant_q), FB'(p4_q), FB'(t3_q), FB'(t2_q), FB'(specular_setup_pkg::E3)};
    specular_setup_fmul #(.N(FN), .ABits(FA), .BBits(FB), .TileBits(TileBits), .SetupII(SetupII)) u_fmul (
      .clk_i (clk_i), .en_i (en_i), .a_i (f_a), .b_i (f_b), .p_o (f_p), .pc_o (f_pc));
    for (genvar i = 0; i < FN - 1; i++) begin : gen_lane
      assign pm[i] = f_pc[i*(FA+FB) +: 64];
    end
    // mant scale: the unit's own register is stage 6's.
    assign prod = f_p[(FN-1)*(FA+FB) +: PW];
    logic unused_fold;
    assign unused_fold = ^{f_p, f_pc};  // each lane's low 64 bits: mul64's
  end else begin : gen_inline
    assign pm[0] = specular_setup_pkg::mul64(64'(g_q[1]), specular_setup_pkg::E3);
    assign pm[1] = specular_setup_pkg::mul64(64'(g_q[2]), 64'(t2_q));
    assign pm[2] = specular_setup_pkg::mul64(64'(g_q[3]), 64'(t3_q));
    assign pm[3] = specular_setup_pkg::mul64(64'(pow_q[4]), 64'(p4_q));
    logic [PW-1:0] prod_q;
    logic signed [63:0] prod_d;  // (a cast of a call: not Icarus 11)
    logic               unused_prod_hi;
    assign prod_d = specular_setup_pkg::mul64(64'(mant_q), 64'(scale_q[5]));
    assign unused_prod_hi = ^prod_d[63:PW];  // below 2^PW (the comment of PW)
    always_ff @(posedge clk_i) begin
      if (en_i) prod_q <= prod_d[PW-1:0];
    end
    assign prod = prod_q;
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      g_q[1]     <= f_d[LoBits-1:0];
      ei_q       <= ei_d;
      scale_q[1] <= scale_i;
      for (int s = 2; s <= 6; s++) begin
        scale_q[s] <= scale_q[s-1];
      end
      for (int s = 2; s <= 4; s++) begin
        g_q[s] <= g_q[s-1];
      end
      pow_q[2] <= pow_j;
      pow_q[3] <= pow_q[2];
      pow_q[4] <= pow_q[3];
      // stage 2: the decode of ei (ShW-bit arithmetic: exact for ei in [MinEi, MaxEi])
      sh_q[2]   <= ShW'(LogFrac - 1) - ShW'(ei_q);
      zero_q[2] <= ei_q < $signed(EiW'(MinEi));
      big_q[2]  <= ei_q > $signed(EiW'(MaxEi));
      for (int s = 3; s <= 7; s++) begin
        big_q[s] <= big_q[s-1];
      end
      for (int s = 3; s <= 6; s++) begin
        zero_q[s] <= zero_q[s-1];
      end
      for (int s = 3; s <= 7; s++) begin
        sh_q[s] <= sh_q[s-1];
      end
      // the Horner steps and mant
      t2_q   <= TW'((pm[0] + AddE2) >>> LogFrac);
      t3_q   <= TW'((pm[1] + AddE1) >>> LogFrac);
      p4_q   <= TW'((pm[2] + AddOne) >>> LogFrac);
      mant_q <= TW'((pm[3] + AddMant) >>> LogFrac);
      // stage 7: (x + 2^(s-1)) >>> s = ((x >>> (s - 1)) + 1) >>> 1
      shift_q <= shift_d;
      zero_q[7] <= zero_q[6] || scale_q[6] == '0;
    end
  end

  specular_setup_rshift #(.InW(PW), .OutW(VW), .SW(ShW), .Signed(1'b0)) u_shift (
    .a_i (prod), .s_i (sh_q[6]), .y_o (shift_d));

  // Stage 8.
  logic [VW-1:0] v;
  assign v = (shift_q + VW'(1)) >> 1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (zero_q[7]) begin
        c_o   <= '0;
        sat_o <= 1'b0;
      end else if (big_q[7] || |v[VW-1:CBits]) begin
        c_o   <= '1;
        sat_o <= 1'b1;
      end else begin
        c_o   <= v[CBits-1:0];
        sat_o <= 1'b0;
      end
    end
  end

  logic unused_g;
  assign unused_g = ^g_q[4];

endmodule
