// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup: the scanline setup in hardware (docs/setup_hw.md). Geometry spans in
// (docs/interfaces.md#geometry-span-interface), specular_stream's span descriptors out
// (C, psi0, dpsi, n, l, tag) and the setup's status, one span per clock (SetupII = 1) or
// at most one every SetupII clocks (docs/setup_hw.md#sharing-over-setupii-clocks). Bit-exact golden
// model: host::fixed::setup_fixed (model/host/setup_fixed.hpp), whose steps and widths are
// those below.
//
// Ports:
//   clk_i, rst_ni                      clock; asynchronous reset, active low: drops every
//                                      span in flight, the setup is empty afterwards
//   geo_*                              the geometry span interface
//                                      (rtl/prim/specular_geo_ports.svh; NBits 10,
//                                      LenBits 11, CBits 16)
//   span_valid_o, span_ready_i         span descriptor handshake (specular_stream's span side)
//   span_c_o[16], span_psi0_o[32], span_dpsi_o[32], span_n_o[10], span_len_o[11], span_tag_o
//   span_status_o[3]                   SetupStatus of scanline_setup.hpp: 0 ok, 1 invalid_input,
//                                      2 undefined_halfway, 3 opposite_normals, 4 opposite_halfway
//
// Handshake, AXI4-Stream rules on both sides. span_valid_o and the descriptor are
// registers of a two-entry output buffer (specular_out_buf) and hold until the transfer.
// geo_ready_o is a register (the buffer's room): high when the pipeline advances at the next
// edge; every stage is enabled by it, so a stall freezes the whole pipeline. With
// span_ready_i high, one span per clock is accepted and emitted (SetupII = 1), Latency
// clocks after its acceptance. With SetupII > 1, geo_ready_o is also low at the advancing
// clocks whose count modulo SetupII is not 0 (a function of registers still).
//
// Pipeline (tau: registers after the input register; the golden model's steps):
//   0        the input register; decode: invalid_input, undefined_halfway, opposite normals
//            (the integer cross product)
//   1..9     normalize N1, N2, H1, He (four specular_setup_norm)
//   10..18   normalize the bisector N1 + N2
//   19, 20   y = S_m(He) (He for opposite normals)      21, 22: H2 = S_N1(y)
//   23       cos t1, x = H1.H2, the flat and opposite-halfway tests   24: W
//   25..33   normalize W                                34: |W|, N1.u
//   35..83   two CORDIC vectorings: gamma; lambda and A K
//   84       gamma (0 flat, pi opposite halfway), A, psi0, floor(log2 l); the 1/l ROM is read
//   85       dpsi                                       85..90: log2 A
//   91       n log2 A                                   92..99: C
//   then     the output buffer
// The tau above and the suffixes of the signals are SetupII = 1's. Sharing
// (docs/setup_hw.md#sharing-over-setupii-clocks: one instance serves sites whose input
// positions differ modulo SetupII, the site picked by the valid bit of its position, vld):
//   SetupII 2  the code normalizers on two instances (N1, H1 and N2, He; H1 and He enter at
//              tau 1); the bisector's and W's normalizer on one; the six dot products on
//              three (cos t1 computed at tau 19); the two CORDICs on one (lambda's a clock
//              behind gamma's: every step from the CORDICs on one tau later)
//   SetupII 4  the code normalizers on one instance (N1, N2, H1, He entering at tau 0, 1,
//              2, 3: every step from the bisector on one tau later); the two Q44
//              normalizers on one; the dot products on two; the two reflections' scaled
//              subtractions on one; the CORDICs on one (one more tau)
//   SetupII 8  as 4, but one normalizer (InW = VecW) for all six sites: the codes entering at
//              tau 0, 1, 5, 6 and N1 + N2 a clock late, so the bisector (tau 11) and W
//              (tau 26) fall on positions 3 and 2 modulo 8 (one more tau)
// Patent block numbers do not apply: the patent leaves the setup to the host.

`include "specular_assert.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module specular_setup #(
  parameter int VecBits       = 18,
  parameter int TagBits       = 16,
  // 1: the end halfway vector equals the first (a directional light and a viewer at
  // infinity): geo_he_i is ignored and its normalizer is not built.
  parameter bit HeEqH1        = 1'b0,
  // Initiation interval: at most one span every SetupII clocks (1, 2, 4 or 8), the hardware
  // shared over those clocks (docs/setup_hw.md#sharing-over-setupii-clocks).
  parameter int SetupII       = 1,
  parameter     RsqrtSeedFile = "roms/setup/rsqrt_seed.hex",
  parameter     LogRecipFile  = "roms/setup/log_recip.hex",
  parameter     LogValueFile  = "roms/setup/log_value.hex",
  parameter     Exp2File      = "roms/setup/exp2.hex",
  parameter     RecipLenFile  = "roms/setup/recip_len.hex",
  // The register formats (specular_setup_pkg): the widths of the geometry ports
  // (rtl/prim/specular_geo_ports.svh) and of the descriptor.
  localparam int CBits        = specular_setup_pkg::SpanCBits,
  localparam int AngleBits    = specular_setup_pkg::SpanAngleBits,
  localparam int NBits        = specular_setup_pkg::SpanNBits,
  localparam int LenBits      = specular_setup_pkg::SpanLenBits
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_SPAN_PORTS(output, input, _o, _i),
  output logic [2:0]           span_status_o
);

  // The setup's widths and constants (Yosys 0.23 has no import inside a module).
  localparam int VecW         = specular_setup_pkg::VecW;
  localparam int VecTBits     = 3 * VecW;  // a vec_t
  localparam logic signed [VecW-1:0] Floor = VecW'(specular_setup_pkg::ChordFloor);
  localparam int UnitFrac     = specular_setup_pkg::UnitFrac;
  localparam int CordicFrac   = specular_setup_pkg::CordicFrac;
  localparam int RecipLenFrac = specular_setup_pkg::RecipLenFrac;
  localparam int GammaFrac    = specular_setup_pkg::GammaFrac;
  localparam int CordicW      = specular_setup_pkg::CordicW;
  localparam int AmpW         = specular_setup_pkg::AmpW;
  localparam int GammaW       = GammaFrac + 3;  // gamma in [0, pi], Q30
  localparam int GainFrac     = specular_setup_pkg::GainFrac;
  localparam int NormStages   = specular_setup_pkg::NormStages;
  localparam int CordicStages = specular_setup_pkg::CordicStages;
  localparam int LogStages    = specular_setup_pkg::LogStages;
  localparam int ExpStages    = specular_setup_pkg::ExpStages;
  localparam logic signed [CordicW-1:0] Pi = CordicW'(specular_setup_pkg::Pi);
  localparam logic signed [63:0] InvGain = specular_setup_pkg::InvGain;

  localparam int AngleFrac = 28;  // psi0 and dpsi: fraction bits (Format's)
  localparam int MaxN      = 1000;
  localparam int Up        = CordicFrac - UnitFrac;  // Q44 -> Q50
  // Sharing (docs/setup_hw.md#sharing-over-setupii-clocks). The normalizers of the codes:
  // sites N1, N2, H1, He (j = 0 .. 3; He not with HeEqH1) on ceil(sites / SetupII) instances,
  // site j on instance j mod CodeInst, entering Off(j) = j / CodeInst clocks late. SetupII = 8:
  // one normalizer (InW = VecW) for all six sites, the codes entering at tau 0, 1, 5, 6 and
  // N1 + N2 a clock late (BisPad), so that the bisector (tau 11) and W (tau 26) fall on the
  // free positions 3 and 2 modulo 8.
  localparam bit AllNorm   = SetupII == 8;
  localparam int CodeSites = HeEqH1 ? 3 : 4;
  localparam int CodeInst  = (CodeSites + SetupII - 1) / SetupII;
  localparam int OffN2     = 1 / CodeInst;
  localparam int OffH1     = AllNorm ? 5 : 2 / CodeInst;
  localparam int OffHe     = HeEqH1 ? OffH1 : AllNorm ? 6 : 3 / CodeInst;  // He = H1 with HeEqH1
  localparam int BisPad    = AllNorm ? 1 : 0;
  // The two CORDICs on one instance (SetupII > 1): lambda's enters a clock after gamma's.
  localparam int CordicSkew = SetupII > 1 ? 1 : 0;
  // tau of each step's output (see the header; the numbers are SetupII = 1's).
  localparam int TNorm1  = NormStages + OffN2 + BisPad;  // 9: N1 + N2 (the bisector's input)
  localparam int TNorm2  = TNorm1 + NormStages;      // 18
  localparam int TH2     = TNorm2 + 4;               // 22
  localparam int TTest   = TH2 + 1;                  // 23
  localparam int TW      = TTest + 1;                // 24
  localparam int TU      = TW + NormStages;          // 33
  localparam int TNu     = TU + 1;                   // 34
  localparam int TCordic = TNu + CordicStages + CordicSkew;  // 83
  localparam int TRegs   = TCordic + 1;              // 84
  localparam int TLog    = TRegs + LogStages;        // 90
  localparam int TE      = TLog + 1;                 // 91
  localparam int TC      = TE + ExpStages;           // 99
  localparam int OutBits = CBits + 2 * AngleBits + NBits + LenBits + TagBits + 3;

  if (VecBits < 2 || VecBits > 24 || TagBits < 1) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup: VecBits must be in 2..24 and TagBits >= 1")
  end
  if (SetupII != 1 && SetupII != 2 && SetupII != 4 && SetupII != 8) begin : gen_ii_check
    `SPEC_PARAM_ERROR("specular_setup: SetupII must be 1, 2, 4 or 8")
  end
  // The bisector's and W's normalizer share one instance: their input positions must differ
  // modulo SetupII.
  if (SetupII > 1 && (TW - TNorm1) % SetupII == 0) begin : gen_share_check
    `SPEC_PARAM_ERROR("specular_setup: the bisector's and W's normalizer collide modulo SetupII")
  end
  // SetupII = 8: the bisector and W apart from the codes' positions 0, 1, 5, 6 modulo 8.
  localparam logic [7:0] CodePos8 = 8'h63;  // positions 0, 1, 5, 6
  if (AllNorm && (CodePos8[TNorm1 % 8] || CodePos8[TW % 8])) begin : gen_all_check
    `SPEC_PARAM_ERROR("specular_setup: the bisector's or W's normalizer collides with a code's modulo 8")
  end

  typedef logic signed [VecW-1:0] comp_t;
  typedef struct packed {
    comp_t z;
    comp_t y;
    comp_t x;
  } vec_t;

  logic adv;
  logic geo_take;  // the input register takes geo_valid_i (at an advancing clock)
  // Spacing (docs/setup_hw.md#sharing-over-setupii-clocks): with SetupII > 1 a span is
  // accepted only when the count of advancing clocks modulo SetupII (phase_q) is 0, so every
  // span in flight sits at a position congruent to every other's modulo SetupII, and after
  // an accept geo_ready_o is low for the next SetupII - 1 advancing clocks. A stall freezes
  // the count; reset clears it. geo_ready_o stays a function of registers.
  if (SetupII == 1) begin : gen_ii1
    assign geo_ready_o = adv;
    assign geo_take    = geo_valid_i;
  end else begin : gen_ii
    localparam int PhaseBits = $clog2(SetupII);
    logic [PhaseBits-1:0] phase_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        phase_q <= '0;
      end else if (adv) begin
        phase_q <= phase_q + PhaseBits'(1);  // SetupII is a power of two: wraps at SetupII
      end
    end
    assign geo_ready_o = adv && phase_q == '0;
    assign geo_take    = geo_valid_i && phase_q == '0;
  end

  // ---- tau 0: the input register ----
  logic                 in_valid_q;
  logic [3*VecBits-1:0] n1_q, n2_q, h1_q, he_q;
  logic [NBits-1:0]     n_q;
  logic [LenBits-1:0]   len_q;
  logic [CBits-1:0]     scale_q;
  logic [TagBits-1:0]   tag_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      in_valid_q <= 1'b0;
    end else if (adv) begin
      in_valid_q <= geo_take;
    end
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      n1_q    <= geo_n1_i;
      n2_q    <= geo_n2_i;
      h1_q    <= geo_h1_i;
      he_q    <= HeEqH1 ? geo_h1_i : geo_he_i;
      n_q     <= geo_n_i;
      len_q   <= geo_len_i;
      scale_q <= geo_scale_i;
      tag_q   <= geo_tag_i;
    end
  end

  // Decode (combinational on tau 0).
  vec_t c1, c2;
  assign c1 = {VecW'($signed(n1_q[3*VecBits-1:2*VecBits])), VecW'($signed(n1_q[2*VecBits-1:VecBits])),
               VecW'($signed(n1_q[VecBits-1:0]))};
  assign c2 = {VecW'($signed(n2_q[3*VecBits-1:2*VecBits])), VecW'($signed(n2_q[2*VecBits-1:VecBits])),
               VecW'($signed(n2_q[VecBits-1:0]))};
  logic invalid, undefined, opp_normals;
  logic signed [63:0] cr_x, cr_y, cr_z, cdot;
  always_comb begin
    cr_x = 64'(c1.y) * 64'(c2.z) - 64'(c1.z) * 64'(c2.y);
    cr_y = 64'(c1.z) * 64'(c2.x) - 64'(c1.x) * 64'(c2.z);
    cr_z = 64'(c1.x) * 64'(c2.y) - 64'(c1.y) * 64'(c2.x);
    cdot = 64'(c1.x) * 64'(c2.x) + 64'(c1.y) * 64'(c2.y) + 64'(c1.z) * 64'(c2.z);
    invalid     = n_q == '0 || n_q > NBits'(MaxN) || n1_q == '0 || n2_q == '0;
    undefined   = h1_q == '0 || he_q == '0;
    opp_normals = cr_x == 0 && cr_y == 0 && cr_z == 0 && cdot < 0;
  end

  // The valid bit of every position (vld[t]: a span at tau t), which selects the site of a
  // shared instance; SetupII = 1 shares nothing and builds none.
  logic [TC:0] vld;
  if (SetupII == 1) begin : gen_vld_none
    assign vld = '0;
  end else begin : gen_vld
    logic [TC:1] vld_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        vld_q <= '0;
      end else if (adv) begin
        vld_q <= {vld_q[TC-1:1], in_valid_q};
      end
    end
    assign vld = {vld_q, in_valid_q};
  end

  // ---- Normalizers of the codes: site j from tau Off(j) to NormStages + Off(j) ----
  // Flat arrays (Yosys 0.23 has no multi-dimensional packed arrays): site j's code is
  // code[j*CodeW +: CodeW], instance i's unit vector code_unit[i*VecTBits +: VecTBits].
  localparam int CodeW = 3 * VecBits;
  logic [CodeSites*CodeW-1:0]   code, code_dl;
  logic [CodeSites-1:0]         code_pick;  // site j's span is at its entry position
  logic [CodeInst*VecTBits-1:0] code_unit;
  vec_t n1u, n2u, h1u, heu, mu, uu, w_q;
  assign code[3*CodeW-1:0] = {h1_q, n2_q, n1_q};
  if (!HeEqH1) begin : gen_code_he
    assign code[4*CodeW-1 -: CodeW] = he_q;
  end
  for (genvar j = 0; j < CodeSites; j++) begin : gen_code_site
    localparam int Off = (AllNorm && j >= 2) ? j + 3 : j / CodeInst;
    specular_delay #(.Width(CodeW), .Depth(Off), .Reset(1'b0)) u_dly_code (
      .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (code[j*CodeW +: CodeW]), .q_o (code_dl[j*CodeW +: CodeW])
    );
    assign code_pick[j] = vld[Off];
  end
  vec_t n1m, msum;  // N1 at TNorm1, N1 + N2
  for (genvar i = 0; i < CodeInst; i++) begin : gen_norm_code
    // (no struct inside a generate block: Yosys 0.23 cannot resolve its members there)
    logic [CodeW-1:0]  sel;
    logic [VecW-1:0]   ux, uy, uz;
    always_comb begin
      sel = code_dl[i*CodeW +: CodeW];  // the site entering at offset 0, unless a later one's span is there
      for (int j = i + CodeInst; j < CodeSites; j = j + CodeInst) begin
        if (code_pick[j]) sel = code_dl[j*CodeW +: CodeW];
      end
    end
    if (AllNorm) begin : gen_all
      // The one normalizer of SetupII = 8 (InW = VecW: the codes sign-extended, the same
      // arithmetic): W, the bisector, else a code.
      logic [VecTBits-1:0] all_sel;
      always_comb begin
        all_sel = {VecW'($signed(sel[3*VecBits-1:2*VecBits])), VecW'($signed(sel[2*VecBits-1:VecBits])),
                   VecW'($signed(sel[VecBits-1:0]))};
        if (vld[TNorm1]) all_sel = msum;
        if (vld[TW]) all_sel = w_q;
      end
      specular_setup_norm #(.RsqrtSeedFile(RsqrtSeedFile)) u_norm (
        .clk_i (clk_i), .en_i (adv),
        .x_i (all_sel[VecW-1:0]), .y_i (all_sel[2*VecW-1:VecW]), .z_i (all_sel[3*VecW-1:2*VecW]),
        .x_o (ux), .y_o (uy), .z_o (uz)
      );
    end else begin : gen_code
      specular_setup_norm #(.InW(VecBits), .RsqrtSeedFile(RsqrtSeedFile)) u_norm (
        .clk_i (clk_i), .en_i (adv),
        .x_i (sel[VecBits-1:0]), .y_i (sel[2*VecBits-1:VecBits]), .z_i (sel[3*VecBits-1:2*VecBits]),
        .x_o (ux), .y_o (uy), .z_o (uz)
      );
    end
    assign code_unit[i*VecTBits +: VecTBits] = {uz, uy, ux};
  end
  assign n1u = code_unit[0 +: VecTBits];
  assign n2u = code_unit[(1 % CodeInst)*VecTBits +: VecTBits];
  assign h1u = code_unit[(2 % CodeInst)*VecTBits +: VecTBits];
  if (HeEqH1) begin : gen_he_eq_h1
    assign heu = h1u;
  end else begin : gen_he
    assign heu = code_unit[(3 % CodeInst)*VecTBits +: VecTBits];
  end

  // ---- Normalizers of the bisector (tau TNorm1 -> TNorm2) and of W (tau TW -> TU) ----
  vec_t n2m;  // N2 at TNorm1
  specular_delay #(.Width(VecTBits), .Depth(OffN2 + BisPad), .Reset(1'b0)) u_dly_n1m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1u), .q_o (n1m)
  );
  specular_delay #(.Width(VecTBits), .Depth(BisPad), .Reset(1'b0)) u_dly_n2m (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n2u), .q_o (n2m)
  );
  assign msum = {n1m.z + n2m.z, n1m.y + n2m.y, n1m.x + n2m.x};
  if (AllNorm) begin : gen_norm_q44_all
    assign mu = code_unit;  // the one normalizer (above)
    assign uu = code_unit;
  end else if (SetupII == 1) begin : gen_norm_q44
    specular_setup_norm #(.RsqrtSeedFile(RsqrtSeedFile)) u_norm_m (
      .clk_i (clk_i), .en_i (adv), .x_i (msum.x), .y_i (msum.y), .z_i (msum.z), .x_o (mu.x), .y_o (mu.y), .z_o (mu.z)
    );
    specular_setup_norm #(.RsqrtSeedFile(RsqrtSeedFile)) u_norm_w (
      .clk_i (clk_i), .en_i (adv), .x_i (w_q.x), .y_i (w_q.y), .z_i (w_q.z), .x_o (uu.x), .y_o (uu.y), .z_o (uu.z)
    );
  end else begin : gen_norm_q44_shared
    logic [VecTBits-1:0] sel;
    logic [VecW-1:0]     ux, uy, uz;
    assign sel = vld[TW] ? w_q : msum;
    specular_setup_norm #(.RsqrtSeedFile(RsqrtSeedFile)) u_norm_mw (
      .clk_i (clk_i), .en_i (adv), .x_i (sel[VecW-1:0]), .y_i (sel[2*VecW-1:VecW]), .z_i (sel[3*VecW-1:2*VecW]),
      .x_o (ux), .y_o (uy), .z_o (uz)
    );
    assign mu = {uz, uy, ux};
    assign uu = {uz, uy, ux};
  end

  // Vectors beside the bisector's normalizer: N1, H1 and He to TNorm2 (18).
  vec_t n1_18, h1_18, he_18;
  specular_delay #(.Width(VecTBits), .Depth(NormStages), .Reset(1'b0)) u_dly_n1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1m), .q_o (n1_18)
  );
  specular_delay #(.Width(VecTBits), .Depth(TNorm2 - NormStages - OffH1), .Reset(1'b0)) u_dly_h1 (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (h1u), .q_o (h1_18)
  );
  specular_delay #(.Width(VecTBits), .Depth(TNorm2 - NormStages - OffHe), .Reset(1'b0)) u_dly_he (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (heu), .q_o (he_18)
  );
  // Opposite normals at tau 19.
  logic opp_n_19;
  specular_delay #(.Width(1), .Depth(TNorm2 + 1), .Reset(1'b0)) u_dly_oppn (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (opp_normals), .q_o (opp_n_19)
  );

  // a.b rounded once, Q44.
  function automatic logic signed [63:0] dot(input logic signed [VecW-1:0] ax, input logic signed [VecW-1:0] ay,
                                             input logic signed [VecW-1:0] az, input logic signed [VecW-1:0] bx,
                                             input logic signed [VecW-1:0] by, input logic signed [VecW-1:0] bz);
    dot = 64'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(64'(ax), 64'(bx)) +
                                               specular_setup_pkg::mul(64'(ay), 64'(by)) +
                                               specular_setup_pkg::mul(64'(az), 64'(bz)), UnitFrac));
  endfunction
  // One component of v - s u 2^(44 - sh) (sh = 43: a reflection's v - 2 (v.u) u).
  function automatic logic signed [VecW-1:0] sub_scaled(input logic signed [VecW-1:0] v, input logic signed [63:0] sc,
                                                        input logic signed [VecW-1:0] u, input int sh);
    sub_scaled = v - VecW'(specular_setup_pkg::rshift_round(specular_setup_pkg::mul(sc, 64'(u)), sh));
  endfunction
  function automatic logic within_floor(input logic signed [VecW-1:0] d);
    within_floor = d <= Floor && d >= -Floor;
  endfunction
  // On whole vec_t words ({z, y, x}; Yosys 0.23 takes no struct arguments).
  function automatic logic signed [63:0] dotv(input logic [VecTBits-1:0] a, input logic [VecTBits-1:0] b);
    dotv = dot(a[VecW-1:0], a[2*VecW-1:VecW], a[3*VecW-1:2*VecW], b[VecW-1:0], b[2*VecW-1:VecW], b[3*VecW-1:2*VecW]);
  endfunction
  // v - s u 2^(43 - 44): a reflection's v - 2 (v.u) u.
  function automatic logic [VecTBits-1:0] reflect(input logic [VecTBits-1:0] v, input logic signed [63:0] sc,
                                                  input logic [VecTBits-1:0] u);
    reflect = {sub_scaled(v[3*VecW-1:2*VecW], sc, u[3*VecW-1:2*VecW], UnitFrac - 1),
               sub_scaled(v[2*VecW-1:VecW], sc, u[2*VecW-1:VecW], UnitFrac - 1),
               sub_scaled(v[VecW-1:0], sc, u[VecW-1:0], UnitFrac - 1)};
  endfunction

  // ---- tau 19 .. 24: the rotation, the tests, W ----
  vec_t he_19, m_19, y_20, y_21, h2_22, h2_23, h1_23, n1_23;
  vec_t n1_19, n1_20, n1_21, n1_22, h1_19, h1_20, h1_21, h1_22;
  logic signed [63:0] s1_19, s2_21, cos_t1_23, x_23;
  logic flat_23, opp_h_23;
  vec_t w_33, n1_33, n1_24;

  // The dot products (one stage each): s1 = He.m at tau 18, s2 = y.N1 at 20, x = H1.H2 at 22,
  // |W| = u.W and N1.u at 33, and cos t1 = N1.H1 (at 22, or at 19 when shared). Shared
  // (input positions distinct modulo SetupII, relative to tau 18: s1 0, cos 1, s2 2, x 4,
  // |W| and N1.u 15): SetupII = 2 {s1, |W|}, {s2, N1.u}, {x, cos}; SetupII = 4
  // {s1, cos, s2, |W|}, {x, N1.u}.
  localparam int TCos = SetupII == 1 ? TTest - 1 : TNorm2 + 1;
  logic signed [63:0] d_s1, d_s2, d_cos, d_x;
  logic signed [CordicW-1:0] d_wl, d_nu;  // |value| < 2^(CordicW-1-UnitFrac)
  if (SetupII == 1) begin : gen_dot
    assign d_s1  = dotv(he_18, mu);
    assign d_s2  = dotv(y_20, n1_20);
    assign d_cos = dotv(n1_22, h1_22);
    assign d_x   = dotv(h1_22, h2_22);
    assign d_wl  = CordicW'(dotv(uu, w_33));
    assign d_nu  = CordicW'(dotv(n1_33, uu));
  end else if (SetupII == 2) begin : gen_dot2
    logic signed [63:0] r0, r1, r2;
    assign r0    = vld[TU] ? dotv(uu, w_33) : dotv(he_18, mu);
    assign r1    = vld[TU] ? dotv(n1_33, uu) : dotv(y_20, n1_20);
    assign r2    = vld[TCos] ? dotv(n1_19, h1_19) : dotv(h1_22, h2_22);
    assign d_s1  = r0;
    assign d_wl  = CordicW'(r0);
    assign d_s2  = r1;
    assign d_nu  = CordicW'(r1);
    assign d_x   = r2;
    assign d_cos = r2;
  end else begin : gen_dot4
    logic [VecTBits-1:0] a0, b0, a1, b1;
    logic signed [63:0]  r0, r1;
    always_comb begin
      {a0, b0} = {he_18, mu};
      if (vld[TCos]) {a0, b0} = {n1_19, h1_19};
      if (vld[TNorm2 + 2]) {a0, b0} = {y_20, n1_20};
      if (vld[TU]) {a0, b0} = {uu, w_33};
      {a1, b1} = vld[TU] ? {n1_33, uu} : {h1_22, h2_22};
    end
    assign r0    = dotv(a0, b0);
    assign r1    = dotv(a1, b1);
    assign d_s1  = r0;
    assign d_cos = r0;
    assign d_s2  = r0;
    assign d_wl  = CordicW'(r0);
    assign d_x   = r1;
    assign d_nu  = CordicW'(r1);
  end
  // cos t1 to tau 23.
  if (SetupII == 1) begin : gen_cos
    always_ff @(posedge clk_i) begin
      if (adv) cos_t1_23 <= d_cos;
    end
  end else begin : gen_cos_early
    specular_delay #(.Width(64), .Depth(TTest - TCos), .Reset(1'b0)) u_dly_cos (
      .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (d_cos), .q_o (cos_t1_23)
    );
  end
  // The reflections (tau 19 and 21): one instance for both with SetupII = 4 (positions 2
  // apart).
  vec_t r_y, r_h2;
  if (SetupII >= 4) begin : gen_refl_shared
    logic [VecTBits-1:0] rv, ru, rr;
    logic signed [63:0]  rs;
    assign {rv, rs, ru} = vld[TNorm2 + 3] ? {y_21, s2_21, n1_21} : {he_19, s1_19, m_19};
    assign rr   = reflect(rv, rs, ru);
    assign r_y  = rr;
    assign r_h2 = rr;
  end else begin : gen_refl
    assign r_y  = reflect(he_19, s1_19, m_19);
    assign r_h2 = reflect(y_21, s2_21, n1_21);
  end
  always_ff @(posedge clk_i) begin
    if (adv) begin
      // tau 19
      s1_19 <= d_s1;
      he_19 <= he_18;
      m_19  <= mu;
      n1_19 <= n1_18;
      h1_19 <= h1_18;
      // tau 20
      y_20  <= opp_n_19 ? he_19 : r_y;
      n1_20 <= n1_19;
      h1_20 <= h1_19;
      // tau 21
      s2_21 <= d_s2;
      y_21  <= y_20;
      n1_21 <= n1_20;
      h1_21 <= h1_20;
      // tau 22
      h2_22 <= r_h2;
      n1_22 <= n1_21;
      h1_22 <= h1_21;
      // tau 23
      x_23      <= d_x;
      flat_23   <= within_floor(h2_22.x - h1_22.x) && within_floor(h2_22.y - h1_22.y) && within_floor(h2_22.z - h1_22.z);
      opp_h_23  <= !(within_floor(h2_22.x - h1_22.x) && within_floor(h2_22.y - h1_22.y) && within_floor(h2_22.z - h1_22.z)) &&
                   within_floor(h2_22.x + h1_22.x) && within_floor(h2_22.y + h1_22.y) && within_floor(h2_22.z + h1_22.z);
      h2_23 <= h2_22;
      h1_23 <= h1_22;
      n1_23 <= n1_22;
      // tau 24
      // W = H2 - x H1, or N1 - cos t1 H1 for opposite halfway vectors. Both arms are
      // written out: Yosys' share pass merges their products into one (the same H1);
      // operands selected first would hide that common operand behind a multiplexer, and
      // each arm would keep multipliers of its own
      // (docs/setup_hw.md#sharing-over-setupii-clocks).
      w_q <= opp_h_23 ? {sub_scaled(n1_23.z, cos_t1_23, h1_23.z, UnitFrac), sub_scaled(n1_23.y, cos_t1_23, h1_23.y, UnitFrac),
                         sub_scaled(n1_23.x, cos_t1_23, h1_23.x, UnitFrac)}
                      : {sub_scaled(h2_23.z, x_23, h1_23.z, UnitFrac), sub_scaled(h2_23.y, x_23, h1_23.y, UnitFrac),
                         sub_scaled(h2_23.x, x_23, h1_23.x, UnitFrac)};
    end
  end

  // Beside the W normalizer: W, N1 (tau 24 -> 33), and the flags, x, cos t1 (tau 23 -> 34).
  always_ff @(posedge clk_i) begin
    if (adv) n1_24 <= n1_23;
  end
  specular_delay #(.Width(VecTBits), .Depth(NormStages), .Reset(1'b0)) u_dly_w (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (w_q), .q_o (w_33)
  );
  specular_delay #(.Width(VecTBits), .Depth(NormStages), .Reset(1'b0)) u_dly_n1b (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n1_24), .q_o (n1_33)
  );
  logic signed [CordicW-1:0] x_34, cos_t1_34;  // dot products, |value| < 2^(CordicW-1-UnitFrac)
  logic flat_33, flat_34;
  specular_delay #(.Width(2 * CordicW), .Depth(TNu - TTest), .Reset(1'b0)) u_dly_xc (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i ({x_23[CordicW-1:0], cos_t1_23[CordicW-1:0]}), .q_o ({x_34, cos_t1_34})
  );
  specular_delay #(.Width(1), .Depth(TU - TTest), .Reset(1'b0)) u_dly_flat (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (flat_23), .q_o (flat_33)
  );

  // ---- tau 34: |W| and N1.u ----
  logic signed [CordicW-1:0] wl_34, nu_34;
  always_ff @(posedge clk_i) begin
    if (adv) begin
      wl_34   <= d_wl;
      nu_34   <= flat_33 ? '0 : d_nu;
      flat_34 <= flat_33;
    end
  end

  // ---- tau 35 .. 83: CORDIC ----
  // gamma = atan2(|W|, x); lambda and A K from (cos t1, N1.u). Shared (SetupII > 1): one
  // instance, lambda's vector entering a clock after gamma's, gamma's angle held a clock.
  logic signed [CordicW-1:0] gamma_angle, gamma_mag_unused, lambda_83, amag_83;
  if (SetupII == 1) begin : gen_cordic
    specular_setup_cordic u_cordic_gamma (
      .clk_i (clk_i), .en_i (adv), .x_i (x_34 <<< Up), .y_i (wl_34 <<< Up),
      .angle_o (gamma_angle), .mag_o (gamma_mag_unused)
    );
    specular_setup_cordic u_cordic_lambda (
      .clk_i (clk_i), .en_i (adv), .x_i (cos_t1_34 <<< Up), .y_i (nu_34 <<< Up),
      .angle_o (lambda_83), .mag_o (amag_83)
    );
  end else begin : gen_cordic_shared
    logic signed [CordicW-1:0] cos_t1_35, nu_35, sel_x, sel_y, angle, mag, gamma_q;
    always_ff @(posedge clk_i) begin
      if (adv) begin
        cos_t1_35 <= cos_t1_34;
        nu_35     <= nu_34;
        gamma_q   <= angle;
      end
    end
    assign sel_x = vld[TNu] ? x_34 : cos_t1_35;
    assign sel_y = vld[TNu] ? wl_34 : nu_35;
    specular_setup_cordic u_cordic (
      .clk_i (clk_i), .en_i (adv), .x_i (sel_x <<< Up), .y_i (sel_y <<< Up), .angle_o (angle), .mag_o (mag)
    );
    assign gamma_angle      = gamma_q;
    assign lambda_83        = angle;
    assign amag_83          = mag;
    assign gamma_mag_unused = '0;
  end
  logic flat_83, opp_h_83;
  specular_delay #(.Width(2), .Depth(TCordic - TTest), .Reset(1'b0)) u_dly_flags (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i ({flat_23, opp_h_23}), .q_o ({flat_83, opp_h_83})
  );
  logic unused_flat_34;
  assign unused_flat_34 = flat_34;

  // Sideband from tau 0: len at tau 83 (the 1/l ROM), n at tau 90, scale at tau 91, the rest
  // at tau 99.
  logic [LenBits-1:0] len_83, len_99;
  logic [NBits-1:0]   n_90, n_99;
  logic [CBits-1:0]   scale_91;
  logic [TagBits-1:0] tag_99;
  logic               invalid_99, undefined_99, opp_n_99, opp_h_99;
  specular_delay #(.Width(LenBits), .Depth(TCordic), .Reset(1'b0)) u_dly_len (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (len_q), .q_o (len_83)
  );
  specular_delay #(.Width(NBits), .Depth(TLog), .Reset(1'b0)) u_dly_n (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (n_q), .q_o (n_90)
  );
  specular_delay #(.Width(CBits), .Depth(TE), .Reset(1'b0)) u_dly_scale (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (scale_q), .q_o (scale_91)
  );
  specular_delay #(.Width(LenBits + NBits + TagBits + 3), .Depth(TC), .Reset(1'b0)) u_dly_out (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv),
    .d_i ({len_q, n_q, tag_q, invalid, undefined, opp_normals}),
    .q_o ({len_99, n_99, tag_99, invalid_99, undefined_99, opp_n_99})
  );
  specular_delay #(.Width(1), .Depth(TC - TTest), .Reset(1'b0)) u_dly_opph (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (opp_h_23), .q_o (opp_h_99)
  );

  // ---- tau 84: gamma, A, psi0, s = floor(log2 l); the 1/l ROM ----
  logic signed [CordicW-1:0] gamma_84;
  logic signed [specular_setup_pkg::AmpW-1:0] a_84;
  logic [AngleBits-1:0] psi0_84, psi0_99;
  logic [RecipLenFrac:0] recip_84;
  logic [3:0] lshift_d, lshift_84;
  always_comb begin
    lshift_d = '0;
    for (int b = 0; b < LenBits; b++) begin
      if (len_83[b]) lshift_d = 4'(b);
    end
  end
  // A K rounded to Q30 (< 2.4: 33 bits) for the product with 1/K.
  logic signed [GainFrac+2:0] ak_83;
  assign ak_83 = (GainFrac + 3)'(specular_setup_pkg::rshift_round64(64'(amag_83), CordicFrac - GainFrac));
  always_ff @(posedge clk_i) begin
    if (adv) begin
      gamma_84  <= flat_83 ? '0 : opp_h_83 ? Pi
                 : gamma_angle < 0 ? '0 : gamma_angle > Pi ? Pi : gamma_angle;
      // A = (A K) (1/K): A K rounded to Q30 first, 1/K in Q30, the product (< 2^62) to Q44.
      a_84      <= AmpW'(specular_setup_pkg::rshift_round64(specular_setup_pkg::mul64(64'(ak_83), InvGain),
                                                         2 * GainFrac - UnitFrac));
      psi0_84   <= AngleBits'(specular_setup_pkg::rshift_round(128'sd0 - 128'(lambda_83), CordicFrac - AngleFrac));
      lshift_84 <= lshift_d;
    end
  end
  specular_rom #(.Width(RecipLenFrac + 1), .AddrBits(LenBits), .File(RecipLenFile)) u_recip_len_rom (
    .clk_i (clk_i), .en_i (adv), .addr_i (len_83), .data_o (recip_84)
  );
  specular_delay #(.Width(AngleBits), .Depth(TC - TRegs), .Reset(1'b0)) u_dly_psi0 (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (psi0_84), .q_o (psi0_99)
  );
  logic a_pos_99;
  specular_delay #(.Width(1), .Depth(TC - TRegs), .Reset(1'b0)) u_dly_apos (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (a_84 > 0), .q_o (a_pos_99)
  );

  // ---- tau 85: dpsi ----
  logic [AngleBits-1:0] dpsi_85, dpsi_99;
  logic signed [GammaW-1:0] gamma30_84;  // gamma rounded to Q30
  assign gamma30_84 = GammaW'(specular_setup_pkg::rshift_round64(64'(gamma_84), CordicFrac - GammaFrac));
  always_ff @(posedge clk_i) begin
    if (adv) begin
      // gamma rounded to Q30, times the mantissa of 1/l, shifted by s = floor(log2 l).
      dpsi_85 <= AngleBits'(specular_setup_pkg::rshift_round64(
                     specular_setup_pkg::mul64(64'(gamma30_84), 64'(recip_84)),
                     GammaFrac + RecipLenFrac + 32'(lshift_84) - AngleFrac));
    end
  end
  specular_delay #(.Width(AngleBits), .Depth(TC - TRegs - 1), .Reset(1'b0)) u_dly_dpsi (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (dpsi_85), .q_o (dpsi_99)
  );

  // ---- tau 85 .. 99: C = scale 2^(n log2 A) ----
  logic signed [specular_setup_pkg::LogW-1:0] log2_90;
  logic signed [specular_setup_pkg::ExpW-1:0] e_91;
  specular_setup_log2 #(.LogRecipFile(LogRecipFile), .LogValueFile(LogValueFile)) u_log2 (
    .clk_i (clk_i), .en_i (adv), .a_i (a_84), .log2_o (log2_90)
  );
  always_ff @(posedge clk_i) begin
    if (adv) e_91 <= specular_setup_pkg::ExpW'(64'($signed({1'b0, n_90})) * 64'(log2_90));
  end
  logic [CBits-1:0] c_99;
  logic             sat_88_unused;
  specular_setup_exp2 #(.CBits(CBits), .Exp2File(Exp2File)) u_exp2 (
    .clk_i (clk_i), .en_i (adv), .e_i (e_91), .scale_i (scale_91), .c_o (c_99), .sat_o (sat_88_unused)
  );

  // ---- tau 99: the descriptor; then the output buffer ----
  logic valid_99;
  specular_delay #(.Width(1), .Depth(TC), .Reset(1'b1)) u_dly_valid (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (in_valid_q), .q_o (valid_99)
  );
  logic             zero_99;
  logic [2:0]       status_99;
  logic [OutBits-1:0] out_d, out_q;
  always_comb begin
    zero_99   = invalid_99 || undefined_99;
    status_99 = invalid_99 ? 3'd1 : undefined_99 ? 3'd2 : opp_h_99 ? 3'd4 : opp_n_99 ? 3'd3 : 3'd0;
    out_d = {zero_99 || !a_pos_99 ? CBits'(0) : c_99,
             zero_99 ? AngleBits'(0) : psi0_99,
             zero_99 ? AngleBits'(0) : dpsi_99,
             n_99, len_99, tag_99, status_99};
  end
  logic unused_adv_d;
  specular_out_buf #(.Width(OutBits)) u_out_buf (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .adv_o      (adv),
    .adv_d_o    (unused_adv_d),  // the advance is adv_o itself here
    .in_valid_i (valid_99),
    .in_data_i  (out_d),
    .px_valid_o (span_valid_o),
    .px_ready_i (span_ready_i),
    .px_data_o  (out_q)
  );
  assign {span_c_o, span_psi0_o, span_dpsi_o, span_n_o, span_len_o, span_tag_o, span_status_o} = out_q;

  logic unused;
  assign unused = ^{gamma_mag_unused, sat_88_unused};

  // Assertions (rtl/prim/specular_assert.svh): the handshake inputs are known.
  `SPEC_ASSERT_KNOWN(GeoValidKnown_A, geo_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(GeoDataKnown_A, `SPECULAR_GEO_DATA(geo_, _i), geo_valid_i && geo_ready_o,
                        clk_i, rst_ni)

endmodule
