// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_norm: a vector of any scale scaled to unit length, Q26, one vector per
// clock: host::fixed::normalize and host::fixed::rsqrt (model/host/setup_fixed.cpp;
// docs/setup_hw.md#the-datapath, steps 2 and 5). The seed of 1/sqrt is interpolated
// between two words of a 385-word table and refined by one Newton-Raphson step; every
// product is a specular_setup_smul and every rounding has a stage of its own, so no stage
// holds more than one carry chain. The zero vector gives 0.
//
//   S1              sq_i = v_i^2 (three multipliers)
//   +1, +2          sq = sq_x + sq_y, + sq_z
//   +3              k = floor((30 - bit width(sq)) / 2), as the shifts it sets (a priority encoder)
//   +4              m = sq 4^k in [2^28, 2^30) (a shifter)
//   +5              the two seed words y0 = word j - 128, y1 = word j - 127, j = m >> 21 (ROMs)
//   +6              d = y0 - y1                  then S(d t): t = the next 9 bits of m
//   +1, +2          rshift_round(d t, 9); seed = y0 - that (Q18)
//   S, +1           s2 = rshift_round(seed^2, 8)
//   S, +1, +2       xs2 = rshift_round(m s2, 30); e = 3 2^28 - xs2
//   S, +1           r = rshift_round(seed e, 19) (Q28)
//   S, +1, +2       u_i = rshift_round(v_i r, 17 - k): v_i shifted left by up to InW - 1
//                   before the product, a shift by one of two constants after it, then
//                   (y + 1) >> 1
// (S: a specular_setup_smul; with SetupII > 1 a lane of the block's specular_setup_fmul,
// specular_setup_pkg::fold_mul_stages stages.) Stages: the localparam Stages
// (specular_setup_pkg::norm_stages).
// en_i freezes every stage. No reset.

`include "specular_assert.svh"

module specular_setup_norm #(
  parameter int InW      = 18,   // input components, signed, any common scale
  parameter int TileBits = 18,
  parameter int SetupII  = 1,    // > 1: the folded setup (one stage per slot of SetupII clocks)
  parameter     SeedFile = "roms/setup/rsqrt_seed.hex"
) (
  input  logic                                             clk_i,
  input  logic                                             en_i,
  input  logic signed [InW-1:0]                            x_i,
  input  logic signed [InW-1:0]                            y_i,
  input  logic signed [InW-1:0]                            z_i,
  output logic signed [specular_setup_pkg::UnitW-1:0] x_o,
  output logic signed [specular_setup_pkg::UnitW-1:0] y_o,
  output logic signed [specular_setup_pkg::UnitW-1:0] z_o
);

  localparam int B        = specular_setup_pkg::RsqrtInBits;   // 30
  localparam int RFrac    = specular_setup_pkg::RsqrtFrac;     // 28
  localparam int Frac     = specular_setup_pkg::Frac;          // 26
  localparam int SFrac    = specular_setup_pkg::SeedFrac;      // 18
  localparam int ABits    = specular_setup_pkg::SeedAddrBits;  // 9
  localparam int IBits    = specular_setup_pkg::SeedInterpBits;
  localparam int SeedW    = specular_setup_pkg::SeedW;         // 20
  localparam int UnitW    = specular_setup_pkg::UnitW;
  localparam int RW       = specular_setup_pkg::RW;            // 32
  localparam int SqW      = 2 * InW + 2;
  localparam int SW       = SeedW + 1;    // seed, signed
  localparam int S2W      = 2 * SeedW - (2 * SFrac - RFrac) + 2;  // s2 < 2^31: 34 bits signed
  localparam int XW       = B + 1;        // m, signed
  localparam int EW       = RFrac + 5;    // e = 3 - x s^2 in (0, 3]: Q28, signed
  localparam int PW       = InW + RW;     // v_i r

  // The schedule: each value's stage.
  localparam int LSq   = specular_setup_pkg::smul_stages(InW, SetupII);
  localparam int LDt   = specular_setup_pkg::smul_stages(SW, SetupII);
  localparam int LSs   = specular_setup_pkg::smul_stages(SW, SetupII);
  localparam int LMs   = specular_setup_pkg::smul_stages(S2W, SetupII);
  localparam int LSe   = specular_setup_pkg::smul_stages(EW, SetupII);
  localparam int LVr   = specular_setup_pkg::smul_stages(RW, SetupII);
  localparam int TSq   = LSq + 2;      // sq
  localparam int TK    = TSq + 1;      // k
  localparam int TM    = TK + 1;       // m
  localparam int TRom  = TM + 1;       // y0, y1
  localparam int TD    = TRom + 1;     // d
  localparam int TRd   = TD + LDt + 1; // rshift_round(d t, 9)
  localparam int TSeed = TRd + 1;      // seed
  localparam int TS2   = TSeed + LSs + 1;
  localparam int TE    = TS2 + LMs + 2;
  localparam int TR    = TE + LSe + 1;
  localparam int Stages = TR + LVr + 2;

  if (Stages != specular_setup_pkg::norm_stages(InW, SetupII)) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_norm: specular_setup_pkg::norm_stages disagrees with the stages built here")
  end

  // Folded (SetupII > 1): the ten products are lanes of one specular_setup_fmul (every
  // operand holds still for the slot, so it serves all the stages); 2 x 2 tiles fit them all.
  localparam int FA = 35, FB = 35, FN = 10;
  if (InW > FA || RW > FB || XW > FA || S2W > FB) begin : gen_fold_width_check
    `SPEC_PARAM_ERROR("specular_setup_norm: the folded unit's lanes are too narrow")
  end
  logic [FN*FA-1:0]      f_a;
  logic [FN*FB-1:0]      f_b;
  logic [FN*(FA+FB)-1:0] f_p;
  logic                  unused_fold;
  if (SetupII > 1) begin : gen_fold_unit
    logic [FN*(FA+FB)-1:0] f_pc;
    specular_setup_fmul #(.N(FN), .ABits(FA), .BBits(FB), .TileBits(TileBits), .SetupII(SetupII),
                          .Stages(specular_setup_pkg::fold_mul_stages(SetupII))) u_fmul (
      .clk_i (clk_i), .en_i (en_i), .a_i (f_a), .b_i (f_b), .p_o (f_p), .pc_o (f_pc));
    assign unused_fold = ^{f_p, f_pc};  // each lane reads its own product's width
  end else begin : gen_no_fold_unit
    assign {f_a, f_b, f_p} = '0;
    assign unused_fold = ^{f_a, f_b, f_p};
  end

  // ---- S1 .. +2: the squared length ----
  logic signed [2*InW-1:0] sqx, sqy, sqz;
  if (SetupII > 1) begin : gen_sqx_fold
    assign f_a[(0)*FA +: FA] = FA'($signed(x_i));
    assign f_b[(0)*FB +: FB] = FB'($signed(x_i));
    assign sqx = (InW + InW)'(f_p[(0)*(FA + FB) +: FA + FB]);
  end else begin : gen_sqx_pipe
    specular_setup_smul #(.ABits(InW), .BBits(InW), .TileBits(TileBits)) u_sqx (
      .clk_i (clk_i), .en_i (en_i), .a_i (x_i), .b_i (x_i), .p_o (sqx));
  end
  if (SetupII > 1) begin : gen_sqy_fold
    assign f_a[(1)*FA +: FA] = FA'($signed(y_i));
    assign f_b[(1)*FB +: FB] = FB'($signed(y_i));
    assign sqy = (InW + InW)'(f_p[(1)*(FA + FB) +: FA + FB]);
  end else begin : gen_sqy_pipe
    specular_setup_smul #(.ABits(InW), .BBits(InW), .TileBits(TileBits)) u_sqy (
      .clk_i (clk_i), .en_i (en_i), .a_i (y_i), .b_i (y_i), .p_o (sqy));
  end
  if (SetupII > 1) begin : gen_sqz_fold
    assign f_a[(2)*FA +: FA] = FA'($signed(z_i));
    assign f_b[(2)*FB +: FB] = FB'($signed(z_i));
    assign sqz = (InW + InW)'(f_p[(2)*(FA + FB) +: FA + FB]);
  end else begin : gen_sqz_pipe
    specular_setup_smul #(.ABits(InW), .BBits(InW), .TileBits(TileBits)) u_sqz (
      .clk_i (clk_i), .en_i (en_i), .a_i (z_i), .b_i (z_i), .p_o (sqz));
  end
  logic [SqW-1:0] sq01_q, sqz_q, sq_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      sq01_q <= SqW'(sqx) + SqW'(sqy);
      sqz_q  <= SqW'(sqz);
      sq_q   <= sq01_q + sqz_q;
    end
  end

  // ---- +3, +4: k and m ----
  // Stage +3 gives the two shift amounts k sets rather than k, so neither shifter has a
  // subtraction in front of it: m = (sq 2^KZ) >> (KZ - 2k) (one right shifter for both signs
  // of k, exact) and s - 1 = RFrac + B/2 - Frac - 1 - k for u_i below.
  localparam int KZ = 2 * (B / 2);
  // The top set bit b of sq: a tree, not a priority loop (specular_setup_prio). With
  // k = floor((B - 1 - b) / 2) and par = (B - 1 + b) mod 2 (so B - 1 - b - par = 2k), each
  // amount is one sum with par as its carry in: KZ - 2k = b + (KZ - B + 1) + par and
  // RFrac + B/2 - Frac - 1 - k = (b + par + 2 (RFrac + B/2 - Frac - 1) - B + 1) / 2.
  localparam int PL = $clog2(SqW);
  localparam int C1 = RFrac + B / 2 - Frac - 1;
  logic          sq_any, sq_any_c;
  logic [PL-1:0] sq_top, sq_top_c;
  logic          par;
  specular_setup_prio #(.W(SqW), .FromTop(1'b0)) u_top (.a_i (sq_q), .any_o (sq_any_c), .value_o (sq_top_c));
  if (SetupII > 1) begin : gen_top_reg
    // Folded, sq_q holds for the slot: the tree's result is registered on every clock (valid
    // from the slot's second), so the stage's registers take the narrow sums from flip-flops,
    // not the tree and a sum in one clock (docs/setup_hw.md#the-folded-setup).
    always_ff @(posedge clk_i) begin
      sq_any <= sq_any_c;
      sq_top <= sq_top_c;
    end
  end else begin : gen_top_wire
    assign sq_any = sq_any_c;
    assign sq_top = sq_top_c;
  end
  assign par = sq_top[0] ^ 1'(B - 1);
  // KZ - 2k lies in 0 .. 2 InW + 2 and is even: its half j in JW bits; the other in 1 .. InW + 2.
  // The narrow sums keep the shifters below as narrow as the amounts.
  localparam int JW = $clog2(InW + 2);
  localparam int UW = $clog2(InW + 3);
  logic [PL:0] j2, ush2;
  assign j2   = (PL + 1)'(sq_top) + (PL + 1)'(KZ - B + 1) + (PL + 1)'(par);
  assign ush2 = (PL + 1)'(sq_top) + (PL + 1)'(2 * C1 - B + 1) + (PL + 1)'(par);
  // sq = 0: k = B/2 (any k: m = 0 and the output 0)
  if (C1 - B / 2 < 0 || C1 - B / 2 >= (1 << UW)) begin : gen_ush_check
    `SPEC_PARAM_ERROR("specular_setup_norm: the shift of sq = 0 does not fit its UW bits")
  end
  logic [JW:0]   msh_d, msh_q;
  logic [UW-1:0] ush_d;
  assign msh_d = sq_any ? {JW'(j2[PL:1]), 1'b0} : (JW + 1)'(KZ - 2 * (B / 2));
  assign ush_d = sq_any ? UW'(ush2[PL:1]) : UW'(C1 - B / 2);
  logic unused_sums;  // even sums; the amounts' ranges
  assign unused_sums = ^{j2[0], ush2[0], j2[PL:1] >> JW, ush2[PL:1] >> UW};
  logic [SqW-1:0]    sq_k;
  logic [SqW+KZ-1:0] sq_z;
  logic [B-1:0]      m_d, m_q;
  logic [UW-1:0]     ush_q;
  assign sq_z = {sq_k, KZ'(0)};
  specular_setup_rshift #(.InW(SqW + KZ), .OutW(B), .SW(JW + 1), .Signed(1'b0)) u_msh (
    .a_i (sq_z), .s_i (msh_q), .y_o (m_d));
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      msh_q <= msh_d;
      ush_q <= ush_d;
      sq_k  <= sq_q;
      m_q   <= m_d;
    end
  end

  // ---- +5: the seed words ----
  logic [ABits-1:0] a0, a1;
  assign a0 = m_q[B-1 -: ABits] - ABits'(128);
  assign a1 = m_q[B-1 -: ABits] - ABits'(127);
  logic [SeedW-1:0] y0, y1;
  specular_rom #(.Width(SeedW), .AddrBits(ABits), .Depth(specular_setup_pkg::SeedWords), .File(SeedFile)) u_rom0 (
    .clk_i (clk_i), .en_i (en_i), .addr_i (a0), .data_o (y0));
  specular_rom #(.Width(SeedW), .AddrBits(ABits), .Depth(specular_setup_pkg::SeedWords), .File(SeedFile)) u_rom1 (
    .clk_i (clk_i), .en_i (en_i), .addr_i (a1), .data_o (y1));
  logic [IBits-1:0] t_rom, t_d;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      t_rom <= m_q[B-ABits-1 -: IBits];
      t_d   <= t_rom;
    end
  end

  // ---- +6 .. : the interpolated seed ----
  logic signed [SW-1:0] d_q, y0_rd, seed_q;
  logic signed [SW+IBits:0] dt;
  logic signed [SW-1:0] rd_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      d_q <= SW'(y0) - SW'(y1);
    end
  end
  if (SetupII > 1) begin : gen_dt_fold
    assign f_a[(3)*FA +: FA] = FA'($signed($signed({1'b0, t_d})));
    assign f_b[(3)*FB +: FB] = FB'($signed(d_q));
    assign dt = (IBits + 1 + SW)'(f_p[(3)*(FA + FB) +: FA + FB]);
  end else begin : gen_dt_pipe
    specular_setup_smul #(.ABits(IBits + 1), .BBits(SW), .TileBits(TileBits)) u_dt (
      .clk_i (clk_i), .en_i (en_i), .a_i ($signed({1'b0, t_d})), .b_i (d_q), .p_o (dt));
  end
  specular_delay #(.Width(SW), .Depth(TRd - TRom), .Reset(1'b0), .Ram(1'b1)) u_dly_y0 (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (SW'(y0)), .q_o (y0_rd));
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rd_q   <= SW'((dt + (SW + IBits + 1)'(1 << (IBits - 1))) >>> IBits);
      seed_q <= y0_rd - rd_q;
    end
  end

  // ---- s2 = seed^2, xs2 = m s2, e, r ----
  logic signed [2*SW-1:0] ss;
  logic signed [S2W-1:0]  s2_q;
  if (SetupII > 1) begin : gen_ss_fold
    assign f_a[(4)*FA +: FA] = FA'($signed(seed_q));
    assign f_b[(4)*FB +: FB] = FB'($signed(seed_q));
    assign ss = (SW + SW)'(f_p[(4)*(FA + FB) +: FA + FB]);
  end else begin : gen_ss_pipe
    specular_setup_smul #(.ABits(SW), .BBits(SW), .TileBits(TileBits)) u_ss (
      .clk_i (clk_i), .en_i (en_i), .a_i (seed_q), .b_i (seed_q), .p_o (ss));
  end
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      s2_q <= S2W'((ss + (2 * SW)'(1 << (2 * SFrac - RFrac - 1))) >>> (2 * SFrac - RFrac));
    end
  end
  logic [B-1:0] m_s2;
  specular_delay #(.Width(B), .Depth(TS2 - TM), .Reset(1'b0), .Ram(1'b1)) u_dly_m (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (m_q), .q_o (m_s2));
  logic signed [XW+S2W-1:0] ms;
  if (SetupII > 1) begin : gen_ms_fold
    assign f_a[(5)*FA +: FA] = FA'($signed($signed({1'b0, m_s2})));
    assign f_b[(5)*FB +: FB] = FB'($signed(s2_q));
    assign ms = (XW + S2W)'(f_p[(5)*(FA + FB) +: FA + FB]);
  end else begin : gen_ms_pipe
    specular_setup_smul #(.ABits(XW), .BBits(S2W), .TileBits(TileBits)) u_ms (
      .clk_i (clk_i), .en_i (en_i), .a_i ($signed({1'b0, m_s2})), .b_i (s2_q), .p_o (ms));
  end
  logic signed [EW-1:0] xs2_q, e_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      xs2_q <= EW'((ms + ((XW + S2W)'(1) <<< (B - 1))) >>> B);
      e_q   <= EW'(64'sd3 <<< RFrac) - xs2_q;
    end
  end
  logic signed [SW-1:0] seed_e;
  specular_delay #(.Width(SW), .Depth(TE - TSeed), .Reset(1'b0), .Ram(1'b1)) u_dly_seed (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (seed_q), .q_o (seed_e));
  logic signed [SW+EW-1:0] se;
  if (SetupII > 1) begin : gen_se_fold
    assign f_a[(6)*FA +: FA] = FA'($signed(seed_e));
    assign f_b[(6)*FB +: FB] = FB'($signed(e_q));
    assign se = (SW + EW)'(f_p[(6)*(FA + FB) +: FA + FB]);
  end else begin : gen_se_pipe
    specular_setup_smul #(.ABits(SW), .BBits(EW), .TileBits(TileBits)) u_se (
      .clk_i (clk_i), .en_i (en_i), .a_i (seed_e), .b_i (e_q), .p_o (se));
  end
  logic signed [RW-1:0] r_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      r_q <= RW'((se + (SW + EW)'(1 << SFrac)) >>> (SFrac + 1));
    end
  end

  // ---- u_i = rshift_round(v_i r, 17 - k), as rshift_round(v'_i r, PS + e) ----
  // |v_i| 2^k <= sqrt(m) < 2^(B/2), and k >= KMin (a nonzero square has at most 2 InW bits), so
  // for k > KMin the exact v'_i = v_i 2^(k - KMin - 1) fits InW signed bits, and v'_i = v_i for
  // k = KMin: the shifter sits on the InW-bit operand before the product, and the product's
  // shift is one of two constants, PS = C1 - KMin - 1 or PS + 1 (e: k = KMin), a multiplexer
  // (docs/setup_hw.md#the-rtl). The left shift by a = k - KMin - 1 is a right shift of
  // v_i 2^(InW-1) by rs = InW - 1 - a = ush + B/2 - C1 (InW - 1 for k = KMin; the zero vector's
  // rs is any: v_i = 0).
  localparam int KMin = B / 2 - InW;
  localparam int PS   = C1 - KMin - 1;
  localparam int RsW  = $clog2(InW);
  if (C1 - B / 2 < 0 || C1 - KMin >= (1 << UW)) begin : gen_rs_check
    `SPEC_PARAM_ERROR("specular_setup_norm: the pre-shift needs ush >= C1 - B/2 >= 0 and C1 - KMin within UW bits")
  end
  logic           e_k, e_u;
  logic [RsW-1:0] rs_k, rs_v;
  assign e_k  = ush_q == UW'(C1 - KMin);
  assign rs_k = e_k ? RsW'(InW - 1) : RsW'(ush_q - UW'(C1 - B / 2));
  specular_delay #(.Width(RsW), .Depth(TR - 1 - TK), .Reset(1'b0), .Ram(1'b1)) u_dly_rs (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (rs_k), .q_o (rs_v));
  specular_delay #(.Width(1), .Depth(TR + LVr - TK), .Reset(1'b0), .Ram(1'b1)) u_dly_e (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (e_k), .q_o (e_u));
  logic [3*InW-1:0]       v_r;
  logic [3*(2*InW-1)-1:0] v_up;
  logic [3*InW-1:0]       vs_d, vs_q;
  specular_delay #(.Width(3 * InW), .Depth(TR - 1), .Reset(1'b0), .Ram(1'b1)) u_dly_v (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({z_i, y_i, x_i}), .q_o (v_r));
  for (genvar i = 0; i < 3; i++) begin : gen_up
    assign v_up[i*(2*InW-1) +: 2*InW-1] = {v_r[i*InW +: InW], (InW - 1)'(0)};
  end
  specular_setup_rshift_n #(.N(3), .InW(2 * InW - 1), .OutW(InW), .SW(RsW), .Signed(1'b1),
                            .SetupII(SetupII)) u_pre (
    .clk_i (clk_i), .en_i (en_i), .a_i (v_up), .s_i (rs_v), .y_o (vs_d));
  always_ff @(posedge clk_i) begin
    if (en_i) vs_q <= vs_d;
  end
  logic signed [UnitW-1:0] u [3];
  for (genvar i = 0; i < 3; i++) begin : gen_scale
    logic signed [PW-1:0]      vr;
    logic signed [UnitW+1:0]   y_q;
    if (SetupII > 1) begin : gen_vr_fold
      assign f_a[(7 + i)*FA +: FA] = FA'($signed(vs_q[i*InW +: InW]));
      assign f_b[(7 + i)*FB +: FB] = FB'($signed(r_q));
      assign vr = (InW + RW)'(f_p[(7 + i)*(FA + FB) +: FA + FB]);
    end else begin : gen_vr_pipe
      specular_setup_smul #(.ABits(InW), .BBits(RW), .TileBits(TileBits)) u_vr (
        .clk_i (clk_i), .en_i (en_i), .a_i (vs_q[i*InW +: InW]), .b_i (r_q), .p_o (vr));
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        // The shift by PS + e, then the rounding.
        y_q  <= e_u ? (UnitW + 2)'(vr >>> (PS + 1)) : (UnitW + 2)'(vr >>> PS);
        u[i] <= UnitW'((y_q + (UnitW + 2)'(1)) >>> 1);
      end
    end
  end
  assign x_o = u[0];
  assign y_o = u[1];
  assign z_o = u[2];

endmodule
