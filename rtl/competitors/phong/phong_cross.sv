// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// The cancellation-free normalization of phong_stream (Cross = 1,
// docs/phong_hw.md#the-cancellation-free-form): w = -log2 cos from sin^2 = |u|^2 / (na nb)
// near the peak (u = a x b) and from cos^2 = d^2 / (na nb) elsewhere, with one interpolated
// reciprocal of the mantissa of na nb, no square root, no Newton step and no subtraction of
// nearly equal numbers. Bit-exact contract (every shift and rounding):
// model/device/phong_model.hpp. Both branches run for every pixel; the sine test picks one
// operand of the shared multiplier X * r and one ROM word of the shared step multiplier.
// phong_pkg::cross_stages(...) stages:
//   1        ea, eb (priority encoders); ed = bit_width(d) - 1; d > 0
//   2        ma, mb, dm (shifts); K0 = ea/2 + eb/2
//   ..       ma * mb; dm * dm beside; u, d scaled by 2^(Q - K0) in the first of these stages
//   a        em, mm, K - ed; u' = u >> em, d' likewise; the reciprocal ROM address
//   b        the reciprocal ROM read; |u'|, |d'|
//   ..       r = v - round(dv t) (phong_mul, rounding, subtraction) beside the squares of
//            |u'|, |d'| (phong_mul), su (two additions) and the sine test su <= sd
//   ..       X * r (phong_mul): X = su (sine) or dm^2 (cosine)
//   p1       s = min(X r >> Sh1, 2^(SFrac-1) - 1); ep = floor(log2 P) (P = X r, cosine)
//   p2       the mantissa of P (shift by ep); E = 2 (K - ed) - ep
//   p3       the g ROM (address s) and log2 ROM (address the mantissa) read; the weight t
//   ..       dv * t (phong_mul; the word of the branch), rounding, v + step
//   ..       s * gv (phong_mul); beside it w = max(0, E 2^LogBits - lg) / 2 (cosine)
//   last     w of the branch; the zero flag (d <= 0)

`include "specular_assert.svh"

module phong_cross #(
  parameter int OpBits      = 18,
  parameter int NormBits    = 16,
  parameter int UBits       = 20,
  parameter int RcpAddrBits = 7,
  parameter int RcpFracBits = 8,
  parameter int RcpBits     = 17,
  parameter int SFrac       = 24,
  parameter int GAddrBits   = 5,
  parameter int GFracBits   = 8,
  parameter int GBits       = 17,
  parameter int DmFrac      = 14,
  parameter int CosFrac     = 16,
  parameter int LogAddrBits = 6,
  parameter int LogFracBits = 10,
  parameter int LogBits     = 23,
  parameter     RcpRomFile  = "",
  parameter     GRomFile    = "",
  parameter     LogRomFile  = "",
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0,
  localparam int WBits      = phong_pkg::cross_w_bits(OpBits, LogBits)
) (
  input  logic                        clk_i,
  input  logic                        en_i,
  input  logic signed [2*OpBits+1:0]  d_i,
  input  logic [2*OpBits-1:0]         na_i,
  input  logic [2*OpBits-1:0]         nb_i,
  input  logic [3*(2*OpBits+1)-1:0]   u_i,
  output logic [WBits-1:0]            w_o,
  output logic                        zero_o
);

  localparam int PBits    = 2 * OpBits;
  localparam int DBits    = 2 * OpBits + 2;
  localparam int UWBits   = 2 * OpBits + 1;          // a component of u = a x b
  localparam int MFrac    = NormBits - 2;
  localparam int EBits    = $clog2(PBits + 1);
  localparam int KBits    = EBits + 1;
  localparam int EdBits   = $clog2(DBits);
  localparam int Q        = UBits - 2;
  localparam int DmBits   = DmFrac + 1;
  localparam int RBits    = RcpBits + 1;             // r in (1/4, 1]
  localparam int RcpDBits = RcpBits - RcpAddrBits + 3;
  localparam int GDBits   = GBits - GAddrBits;
  localparam int LogDBits = LogBits - LogAddrBits + 1;
  localparam int SqBits   = 2 * UBits;
  localparam int XBits    = SqBits > 2 * DmBits ? SqBits : 2 * DmBits;
  localparam int ProdBits = XBits + RBits;
  localparam int Sh1      = 2 * Q + RcpBits - SFrac;  // X r -> s
  localparam int Pf       = 2 * DmFrac + RcpBits;     // fraction bits of P
  localparam int SBits    = SFrac - 1;                // s < 1/2
  localparam int GvBits   = GBits + 1;                // gv <= 1
  localparam int Sh2      = SFrac + GBits - LogBits;  // s gv -> w
  localparam int TF       = GFracBits > LogFracBits ? GFracBits : LogFracBits;
  localparam int TDv      = GDBits > LogDBits ? GDBits : LogDBits;
  localparam int VBits    = (GBits > LogBits ? GBits : LogBits) + 1;
  localparam int ESBits   = $clog2(2 * PBits + 2 * DBits + 8) + 1;  // E, signed
  localparam int MulN     = phong_pkg::mul_stages(NormBits);
  localparam int MulDm    = phong_pkg::mul_stages(DmBits);
  localparam int MulRt    = phong_pkg::mul_stages(RcpFracBits);
  localparam int MulU     = phong_pkg::mul_stages(UBits);
  localparam int MulX     = phong_pkg::mul_stages(RBits);
  localparam int MulT     = phong_pkg::mul_stages(TF);
  localparam int MulG     = phong_pkg::mul_stages(GvBits);
  localparam int T1       = phong_pkg::cross_rcp_sq_stages(RcpFracBits, UBits);
  localparam int Depth    = phong_pkg::cross_stages(NormBits, RcpFracBits, UBits, RcpBits, GFracBits,
                                                    LogFracBits, GBits);

  if (PBits > 64 || RcpAddrBits < 3 || RcpAddrBits + RcpFracBits > NormBits || RcpFracBits < 2 || Sh1 < 0 || Sh2 < 0 ||
      GAddrBits + GFracBits > SBits || LogAddrBits + LogFracBits > CosFrac || Pf < CosFrac + 2 ||
      ProdBits < Sh1 + SBits + 1 || GFracBits < 1 || LogFracBits < 1 || UBits < 4 ||
      MulN + 2 + T1 < MulDm || T1 < MulRt + 2 || T1 < MulU + 3 ||
      Depth != 2 + MulN + 2 + T1 + MulX + 3 + MulT + 2 + MulG + 1) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_cross: 2 OpBits <= 64, the fields of PhongFormat::validate, Sh1, Sh2 >= 0; phong_pkg disagrees")
  end

  // ---- stage 1: exponents ----
  function automatic logic [EdBits-1:0] lead(input logic [DBits-1:0] x);
    lead = '0;
    for (int b = 0; b < DBits - 1; b++) begin
      if (x[b]) lead = EdBits'(b);
    end
  endfunction

  logic [PBits-1:0]        na_1, nb_1;
  logic [EBits-1:0]        ea_1, eb_1;
  logic [EdBits-1:0]       ed_1;
  logic signed [DBits-1:0] d_1;
  logic [3*UWBits-1:0]     u_1;
  logic                    dpos_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      na_1   <= na_i;
      nb_1   <= nb_i;
      ea_1   <= EBits'(phong_pkg::even_exp(64'(na_i)));
      eb_1   <= EBits'(phong_pkg::even_exp(64'(nb_i)));
      ed_1   <= lead(d_i);
      d_1    <= d_i;
      u_1    <= u_i;
      dpos_1 <= !d_i[DBits-1] && d_i != '0;
    end
  end

  // ---- stage 2: mantissas, K0, dm ----
  logic [NormBits-1:0]    ma_2, mb_2;
  logic [KBits-1:0]       k0_2;
  logic [DmBits-1:0]      dm_2;
  logic [EdBits-1:0]      ed_2;
  logic signed [DBits-1:0] d_2;
  logic [3*UWBits-1:0]    u_2;
  logic                   dpos_2;
  logic [PBits+MFrac-1:0] sa, sb;
  logic [DBits+DmFrac-1:0] sdm;
  assign sa  = {na_1, MFrac'(0)} >> ea_1;
  assign sb  = {nb_1, MFrac'(0)} >> eb_1;
  assign sdm = {d_1, DmFrac'(0)} >> ed_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      ma_2   <= sa[NormBits-1:0];
      mb_2   <= sb[NormBits-1:0];
      k0_2   <= (KBits'(ea_1) >> 1) + (KBits'(eb_1) >> 1);
      dm_2   <= sdm[DmBits-1:0];
      ed_2   <= ed_1;
      d_2    <= d_1;
      u_2    <= u_1;
      dpos_2 <= dpos_1;
    end
  end
  logic unused_s2;
  assign unused_s2 = ^{sa[PBits+MFrac-1:NormBits], sb[PBits+MFrac-1:NormBits], sdm[DBits+DmFrac-1:DmBits]};

  // ---- ma * mb and dm * dm; u, d scaled by 2^(Q - K0) beside (floor) ----
  logic [2*NormBits-1:0] m_p;
  phong_mul #(.ABits (NormBits), .BBits (NormBits), .TileBits (MulTileBits)) u_mul_m (
    .clk_i (clk_i), .en_i (en_i), .a_i (ma_2), .b_i (mb_2), .p_o (m_p));
  logic [2*DmBits-1:0] dm2_p;
  phong_mul #(.ABits (DmBits), .BBits (DmBits), .TileBits (MulTileBits)) u_mul_dm (
    .clk_i (clk_i), .en_i (en_i), .a_i (dm_2), .b_i (dm_2), .p_o (dm2_p));

  // |u'| < 2^(Q+1) (docs/phong_hw.md#the-cancellation-free-form); before the em shift one bit more.
  localparam int UsBits = UBits + 2;
  logic signed [UsBits-1:0] us_3 [4];  // u'_0..2 and d' before the em shift
  logic [KBits-1:0]         k0_3;
  logic [EdBits-1:0]        ed_3;
  logic                     dpos_3;
  for (genvar c = 0; c < 4; c++) begin : gen_scale
    logic signed [UWBits+1+Q-1:0] x, xs;
    if (c < 3) begin : gen_u
      assign x = {u_2[c*UWBits + UWBits - 1], u_2[c*UWBits +: UWBits], Q'(0)};
    end else begin : gen_d
      assign x = {1'b0, d_2[DBits-2:0], Q'(0)};  // d > 0 when it is used: the sign bit is not needed
    end
    assign xs = x >>> k0_2;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        us_3[c] <= xs[UsBits-1:0];
      end
    end
    logic unused_xs;
    assign unused_xs = ^xs[UWBits+Q:UsBits];
  end
  logic unused_d2;
  assign unused_d2 = d_2[DBits-1];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      k0_3   <= k0_2;
      ed_3   <= ed_2;
      dpos_3 <= dpos_2;
    end
  end
  logic [4*UsBits-1:0] us_m;
  logic [KBits-1:0]    k0_m;
  logic [EdBits-1:0]   ed_m;
  logic                dpos_m;
  specular_delay #(.Width (4 * UsBits + KBits + EdBits + 1), .Depth (MulN - 1), .Reset (1'b0)) u_us_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i),
    .d_i ({us_3[3], us_3[2], us_3[1], us_3[0], k0_3, ed_3, dpos_3}), .q_o ({us_m, k0_m, ed_m, dpos_m}));

  // ---- stage a: em, mm, K - ed, u' and d', the reciprocal ROM address ----
  logic                      em;
  logic [NormBits-1:0]       mm_c;
  logic [RcpAddrBits-1:0]    ridx_a;
  logic [RcpFracBits-1:0]    rt_a;
  logic signed [UBits:0]     up_a [4];
  logic signed [KBits+1:0]   ked_a;
  logic                      dpos_a;
  logic signed [UsBits-1:0]  ups [4];
  for (genvar c = 0; c < 4; c++) begin : gen_em
    assign ups[c] = $signed(us_m[c*UsBits +: UsBits]) >>> em;
    logic unused_ups;
    assign unused_ups = ^ups[c][UsBits-1:UBits+1];
  end
  assign em   = |m_p[2*NormBits-1:2*NormBits-2];
  assign mm_c = em ? m_p[MFrac+2 +: NormBits] : m_p[MFrac +: NormBits];
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      // mm's top RcpAddrBits bits minus 2^(RcpAddrBits-2): the top two bits (01, 10, 11) less one.
      ridx_a <= {mm_c[NormBits-1:NormBits-2] - 2'd1, mm_c[NormBits-3 -: RcpAddrBits-2]};
      rt_a   <= mm_c[NormBits-RcpAddrBits-1 -: RcpFracBits];
      for (int c = 0; c < 4; c++) begin
        up_a[c] <= ups[c][UBits:0];
      end
      ked_a  <= (KBits + 2)'(k0_m) + (KBits + 2)'(em) - (KBits + 2)'(ed_m);
      dpos_a <= dpos_m;
    end
  end
  logic unused_m;
  assign unused_m = ^m_p[MFrac-1:0];
  if (NormBits > RcpAddrBits + RcpFracBits) begin : gen_unused_mm
    logic unused_mm;
    assign unused_mm = ^mm_c[NormBits-RcpAddrBits-RcpFracBits-1:0];
  end

  // ---- stage b: the reciprocal ROM; |u'|, |d'| ----
  logic [RBits+RcpDBits-1:0] rw_b;
  logic [RcpFracBits-1:0]    rt_b;
  logic [UBits-1:0]          mu_b [4];
  logic signed [KBits+1:0]   ked_b;
  logic                      dpos_b;
  specular_rom #(
    .Width    (RBits + RcpDBits),
    .AddrBits (RcpAddrBits),
    .Depth    (3 << (RcpAddrBits - 2)),
    .File     (RcpRomFile)
  ) u_rcp_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (ridx_a),
    .data_o (rw_b)
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rt_b <= rt_a;
      for (int c = 0; c < 4; c++) begin
        mu_b[c] <= up_a[c][UBits] ? UBits'(-up_a[c]) : UBits'(up_a[c]);
      end
      ked_b  <= ked_a;
      dpos_b <= dpos_a;
    end
  end

  // ---- r = v - round(dv t) ----
  logic [RcpDBits+RcpFracBits-1:0] rp;
  phong_mul #(.ABits (RcpDBits), .BBits (RcpFracBits), .TileBits (MulTileBits)) u_mul_rcp (
    .clk_i (clk_i), .en_i (en_i), .a_i (rw_b[RcpDBits-1:0]), .b_i (rt_b), .p_o (rp));
  logic [RBits-1:0] rv_m;
  specular_delay #(.Width (RBits), .Depth (MulRt), .Reset (1'b0)) u_rv (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (rw_b[RcpDBits +: RBits]), .q_o (rv_m));
  logic [RcpDBits+RcpFracBits-1:0] rr_1;
  logic [RBits-1:0]                rv_1, r_2, r_x;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      rr_1 <= rp + (RcpDBits + RcpFracBits)'(1 << (RcpFracBits - 1));
      rv_1 <= rv_m;
      r_2  <= rv_1 - RBits'(rr_1 >> RcpFracBits);
    end
  end
  specular_delay #(.Width (RBits), .Depth (T1 - MulRt - 2), .Reset (1'b0)) u_r_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (r_2), .q_o (r_x));

  // ---- squares of |u'|, |d'|; su; the sine test ----
  logic [SqBits-1:0] sq [4];
  for (genvar c = 0; c < 4; c++) begin : gen_sq
    phong_mul #(.ABits (UBits), .BBits (UBits), .TileBits (MulTileBits)) u_mul_sq (
      .clk_i (clk_i), .en_i (en_i), .a_i (mu_b[c]), .b_i (mu_b[c]), .p_o (sq[c]));
  end
  logic [SqBits+1:0] su01_1, su2_1, su_2, su_3;
  logic [SqBits-1:0] sd_1, sd_2;
  logic              sine_3;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      su01_1 <= (SqBits + 2)'(sq[0]) + (SqBits + 2)'(sq[1]);
      su2_1  <= (SqBits + 2)'(sq[2]);
      sd_1   <= sq[3];
      su_2   <= su01_1 + su2_1;
      sd_2   <= sd_1;
      su_3   <= su_2;
      sine_3 <= su_2 <= (SqBits + 2)'(sd_2);
    end
  end
  logic [SqBits+1:0] su_x;
  logic              sine_x;
  specular_delay #(.Width (SqBits + 3), .Depth (T1 - MulU - 3), .Reset (1'b0)) u_su_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({su_3, sine_3}), .q_o ({su_x, sine_x}));
  // dm^2 and the side values of stage b to the X * r multiplier.
  logic [2*DmBits-1:0]     dm2_x;
  logic signed [KBits+1:0] ked_x;
  logic                    dpos_x;
  specular_delay #(.Width (2 * DmBits), .Depth (MulN + 2 + T1 - MulDm), .Reset (1'b0)) u_dm2_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (dm2_p), .q_o (dm2_x));
  specular_delay #(.Width (KBits + 3), .Depth (T1), .Reset (1'b0)) u_ked_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({ked_b, dpos_b}), .q_o ({ked_x, dpos_x}));

  // ---- X * r: su (su <= sd < 2^SqBits) or dm^2 ----
  logic [XBits-1:0]    xop;
  logic [ProdBits-1:0] xr;
  assign xop = sine_x ? XBits'(su_x[SqBits-1:0]) : XBits'(dm2_x);
  phong_mul #(.ABits (XBits), .BBits (RBits), .TileBits (MulTileBits)) u_mul_xr (
    .clk_i (clk_i), .en_i (en_i), .a_i (xop), .b_i (r_x), .p_o (xr));
  logic signed [KBits+1:0] ked_p;
  logic                    dpos_p, sine_p;
  specular_delay #(.Width (KBits + 4), .Depth (MulX), .Reset (1'b0)) u_xr_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({ked_x, dpos_x, sine_x}), .q_o ({ked_p, dpos_p, sine_p}));
  logic unused_su;
  assign unused_su = ^su_x[SqBits+1:SqBits];

  // ---- p1: s (clamped below 1/2); ep = floor(log2 P) in -2..1 ----
  logic [SBits-1:0]        s_1;
  logic signed [2:0]       ep_1;
  logic [Pf+1:0]           pp_1;
  logic signed [KBits+1:0] ked_1;
  logic                    dpos_p1, sine_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      s_1     <= (xr[ProdBits-1:Sh1+SBits] != '0) ? {SBits{1'b1}} : xr[Sh1 +: SBits];
      ep_1    <= xr[Pf+1] ? 3'sd1 : xr[Pf] ? 3'sd0 : xr[Pf-1] ? -3'sd1 : -3'sd2;
      pp_1    <= xr[Pf+1:0];
      ked_1   <= ked_p;
      dpos_p1 <= dpos_p;
      sine_1  <= sine_p;
    end
  end
  if (Sh1 > Pf + 2) begin : gen_unused_xr
    logic unused_xr;
    assign unused_xr = ^xr[Sh1-1:Pf+2];
  end

  // ---- p2: the mantissa of P (CosFrac bits below its leading one); E ----
  logic [CosFrac-1:0]      frac_2;
  logic [SBits-1:0]        s_2;
  logic signed [ESBits-1:0] e_2;
  logic                    dpos_2p, sine_2;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      unique case (ep_1)
        3'sd1:   frac_2 <= pp_1[Pf+1-1 -: CosFrac];
        3'sd0:   frac_2 <= pp_1[Pf-1 -: CosFrac];
        -3'sd1:  frac_2 <= pp_1[Pf-1-1 -: CosFrac];
        default: frac_2 <= pp_1[Pf-2-1 -: CosFrac];
      endcase
      s_2     <= s_1;
      e_2     <= ESBits'(2 * ked_1) - ESBits'(ep_1);
      dpos_2p <= dpos_p1;
      sine_2  <= sine_1;
    end
  end
  logic unused_top;
  assign unused_top = pp_1[Pf+1];  // the leading one itself
  if (Pf - 3 - CosFrac >= 0) begin : gen_unused_pp
    logic unused_pp;
    assign unused_pp = ^pp_1[Pf-3-CosFrac:0];
  end

  // ---- p3: the g and log2 ROMs ----
  logic [GBits+GDBits-1:0]     gw_3;
  logic [LogBits+LogDBits-1:0] lw_3;
  logic [TF-1:0]               t_3;
  logic [SBits-1:0]            s_3;
  logic signed [ESBits-1:0]    e_3;
  logic                        dpos_3p, sine_3p;
  specular_rom #(
    .Width    (GBits + GDBits),
    .AddrBits (GAddrBits),
    .File     (GRomFile)
  ) u_g_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (s_2[SBits-1 -: GAddrBits]),
    .data_o (gw_3)
  );
  specular_rom #(
    .Width    (LogBits + LogDBits),
    .AddrBits (LogAddrBits),
    .File     (LogRomFile)
  ) u_log_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (frac_2[CosFrac-1 -: LogAddrBits]),
    .data_o (lw_3)
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      // Both weights scaled to TF bits: (dv t 2^j + 2^(TF-1)) >> TF = (dv t + 2^(F-1)) >> F.
      t_3     <= sine_2 ? TF'(s_2[SBits-GAddrBits-1 -: GFracBits]) << (TF - GFracBits)
                        : TF'(frac_2[CosFrac-LogAddrBits-1 -: LogFracBits]) << (TF - LogFracBits);
      s_3     <= s_2;
      e_3     <= e_2;
      dpos_3p <= dpos_2p;
      sine_3p <= sine_2;
    end
  end
  if (SBits > GAddrBits + GFracBits) begin : gen_unused_s
    logic unused_s;
    assign unused_s = ^s_2[SBits-GAddrBits-GFracBits-1:0];
  end
  if (CosFrac > LogAddrBits + LogFracBits) begin : gen_unused_frac
    logic unused_frac;
    assign unused_frac = ^frac_2[CosFrac-LogAddrBits-LogFracBits-1:0];
  end

  // ---- dv * t of the branch's word, rounding, v + step ----
  logic [TDv-1:0]    dv_3;
  logic [VBits-1:0]  v_3;
  assign dv_3 = sine_3p ? TDv'(gw_3[GDBits-1:0]) : TDv'(lw_3[LogDBits-1:0]);
  assign v_3  = sine_3p ? VBits'(gw_3[GDBits +: GBits]) : VBits'(lw_3[LogDBits +: LogBits]);
  logic [TDv+TF-1:0] tp;
  phong_mul #(.ABits (TDv), .BBits (TF), .TileBits (MulTileBits)) u_mul_step (
    .clk_i (clk_i), .en_i (en_i), .a_i (dv_3), .b_i (t_3), .p_o (tp));
  logic [VBits-1:0]         v_m;
  logic [SBits-1:0]         s_m;
  logic signed [ESBits-1:0] e_m;
  logic                     dpos_sm, sine_m;
  specular_delay #(.Width (VBits + SBits + ESBits + 2), .Depth (MulT), .Reset (1'b0)) u_step_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({v_3, s_3, e_3, dpos_3p, sine_3p}),
    .q_o ({v_m, s_m, e_m, dpos_sm, sine_m}));
  logic [TDv+TF-1:0]        tr_1;
  logic [VBits-1:0]         v_q1, val_2;
  logic [SBits-1:0]         s_q1, s_q2;
  logic signed [ESBits-1:0] e_q1, e_q2;
  logic                     dpos_q1, dpos_q2, sine_q1, sine_q2;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      tr_1    <= tp + (TDv + TF)'(1 << (TF - 1));
      v_q1    <= v_m;
      s_q1    <= s_m;
      e_q1    <= e_m;
      dpos_q1 <= dpos_sm;
      sine_q1 <= sine_m;
      val_2   <= v_q1 + VBits'(tr_1 >> TF);
      s_q2    <= s_q1;
      e_q2    <= e_q1;
      dpos_q2 <= dpos_q1;
      sine_q2 <= sine_q1;
    end
  end

  // ---- sine: w = s gv >> Sh2; cosine: w = max(0, E 2^LogBits - lg) >> 1 ----
  logic [SBits+GvBits-1:0] sg;
  phong_mul #(.ABits (SBits), .BBits (GvBits), .TileBits (MulTileBits)) u_mul_sg (
    .clk_i (clk_i), .en_i (en_i), .a_i (s_q2), .b_i (val_2[GvBits-1:0]), .p_o (sg));
  localparam int DiffBits = ESBits + LogBits + 1;
  logic signed [DiffBits-1:0] diff;
  logic [WBits-1:0]           wc_3, wc_g;
  logic                       dpos_g, sine_g;
  assign diff = (DiffBits'(e_q2) <<< LogBits) - DiffBits'(val_2);
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      wc_3 <= diff[DiffBits-1] ? '0 : WBits'(diff >>> 1);
    end
  end
  specular_delay #(.Width (WBits), .Depth (MulG - 1), .Reset (1'b0)) u_wc_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (wc_3), .q_o (wc_g));
  specular_delay #(.Width (2), .Depth (MulG), .Reset (1'b0)) u_sel_line (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({dpos_q2, sine_q2}), .q_o ({dpos_g, sine_g}));
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      w_o    <= sine_g ? WBits'(sg >> Sh2) : wc_g;
      zero_o <= !dpos_g;
    end
  end

endmodule
