// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Per-span work of phong_stream (docs/phong_hw.md#design): the start value and the step of
// the interpolated vectors, without a division (the cosine does not change when a vector is
// scaled, so the core interpolates A_i = 2^k ((l - i) N1 + i N2) exactly):
//   k  = LenBits - bit_width(l) (l >= 1), L = l << k;  l = 0: k = 0 and L is 2^(LenBits-1)
//   A0 = L * N1, EA = (N2 - N1) << k;  B0 = L * H1, EB = (He - H1) << k
//   ConstH: B0 = H1 << (LenBits - 1), EB = 0 (He is not read, no H multiplier)
// plus the span's flag `zero` (a zero N1, N2, H1 or He, or n outside 1..1000: every pixel 0).
// Headroom (the cross form, docs/phong_hw.md#the-cancellation-free-form): the span's own
// range is kept, every value above scaled by 2^hn (N) and 2^hb (H), hn = VecBits - 1 - the
// bit width of the widest |component| of N1 and N2 (hb: H1 and He, H1 alone with ConstH), and
// the operands are rounded, not floored: A0 and B0 get 2^(RoundBits-1) added (RoundBits =
// AccBits - OpBits, the bits phong_dot drops; 0: none). Bit-exact contract:
// model/device/phong_model.hpp.
//
// A pipeline of phong_pkg::setup_stages(VecBits, Headroom) stages, all enabled by en_i (the
// span pipe moves as a whole); valid_i is the span handshake of the stage-1 register. Stages:
//   1            the span's ports registered
//   2            N2 - N1, He - H1, |N1|, |H1| (|N2|, |He| with Headroom: parallel carry
//                chains), k and L (priority encoder, shift), the zero flag
//   (Headroom)   hn, hb (priority encoders); then the magnitudes and steps shifted by them
//   3 ..         L * |N1| and L * |H1| (phong_mul), the steps shifted by k beside them
//   last         the sign of N1, H1 applied and the rounding constant added (one carry chain)

`include "specular_assert.svh"

module phong_span_setup #(
  parameter int VecBits = 18,
  parameter int LenBits = 11,
  parameter int NBits   = 10,
  parameter int MaxN    = 1000,
  parameter int CBits   = 16,
  parameter int TagBits = 16,
  parameter bit ConstH  = 1'b0,
  parameter bit Headroom  = 1'b0,
  parameter int RoundBits = 0,
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          en_i,
  input  logic                          valid_i,
  input  logic [3*VecBits-1:0]          n1_i,
  input  logic [3*VecBits-1:0]          n2_i,
  input  logic [3*VecBits-1:0]          h1_i,
  input  logic [3*VecBits-1:0]          he_i,
  input  logic [NBits-1:0]              n_i,
  input  logic [LenBits-1:0]            len_i,
  input  logic [CBits-1:0]              scale_i,
  input  logic [TagBits-1:0]            tag_i,
  output logic                          valid_o,
  output logic [3*(VecBits+LenBits)-1:0] a0_o,
  output logic [3*(VecBits+LenBits)-1:0] ea_o,
  output logic [3*(VecBits+LenBits)-1:0] b0_o,
  output logic [3*(VecBits+LenBits)-1:0] eb_o,
  output logic [NBits-1:0]              n_o,
  output logic [LenBits-1:0]            len_o,
  output logic [CBits-1:0]              scale_o,
  output logic [TagBits-1:0]            tag_o,
  output logic                          zero_o
);

  localparam int AccBits  = VecBits + LenBits;
  localparam int MulDepth = phong_pkg::mul_stages(VecBits);
  localparam int Depth    = phong_pkg::setup_stages(VecBits, Headroom);
  localparam int KBits    = $clog2(LenBits + 1);
  localparam int HBits    = $clog2(VecBits);
  localparam logic [AccBits-1:0] Round = RoundBits > 0 ? AccBits'(1) << (RoundBits - 1) : '0;

  // The rounding constant may not carry an accumulator over: RoundBits < VecBits - 1 keeps
  // A_i 2^hn + 2^(RoundBits-1) below 2^(AccBits-1) (docs/phong_hw.md#the-cancellation-free-form).
  if (VecBits < 2 || LenBits < 2 || RoundBits < 0 || RoundBits >= VecBits - 1 ||
      Depth != 3 + (Headroom ? 2 : 0) + MulDepth) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_span_setup: VecBits, LenBits >= 2, 0 <= RoundBits < VecBits - 1; phong_pkg disagrees")
  end

  // ---- valid bits (reset: a reset drops every span in the pipe) ----
  logic [Depth-1:0] vld_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      vld_q <= '0;
    end else if (en_i) begin
      vld_q <= {vld_q[Depth-2:0], valid_i};
    end
  end
  assign valid_o = vld_q[Depth-1];

  // ---- stage 1: the span's ports ----
  logic [3*VecBits-1:0] n1_1, n2_1, h1_1, he_1;
  logic [NBits-1:0]     n_1;
  logic [LenBits-1:0]   len_1;
  logic [CBits-1:0]     scale_1;
  logic [TagBits-1:0]   tag_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      n1_1    <= n1_i;
      n2_1    <= n2_i;
      h1_1    <= h1_i;
      he_1    <= ConstH ? h1_i : he_i;
      n_1     <= n_i;
      len_1   <= len_i;
      scale_1 <= scale_i;
      tag_1   <= tag_i;
    end
  end

  // ---- stage 2: differences, magnitudes, k, L, the zero flag ----
  logic [KBits-1:0]   k_c;
  logic [LenBits-1:0] l_c;
  always_comb begin
    k_c = '0;
    for (int b = 0; b < LenBits; b++) begin
      if (len_1[b]) k_c = KBits'(LenBits - 1 - b);
    end
    l_c = (len_1 == '0) ? LenBits'(1) << (LenBits - 1) : len_1 << k_c;
  end

  logic zero_c;
  always_comb begin
    zero_c = (n_1 == '0) || (32'(n_1) > MaxN);
    for (int v = 0; v < 4; v++) begin
      logic [3*VecBits-1:0] vec;
      unique case (v)
        0:       vec = n1_1;
        1:       vec = n2_1;
        2:       vec = h1_1;
        default: vec = he_1;
      endcase
      if (vec == '0) zero_c = 1'b1;
    end
  end

  logic signed [VecBits:0] dn_2 [3], dh_2 [3];
  logic [VecBits-1:0]      magn_2 [3], magh_2 [3], magn2_2 [3], maghe_2 [3];
  logic [2:0]              sgnn_2, sgnh_2;
  logic [KBits-1:0]        k_2;
  logic [LenBits-1:0]      l_2;
  logic                    zero_2;
  logic [NBits-1:0]        n_2;
  logic [LenBits-1:0]      len_2;
  logic [CBits-1:0]        scale_2;
  logic [TagBits-1:0]      tag_2;
  logic signed [AccBits-1:0] hconst_2 [3];

  for (genvar c = 0; c < 3; c++) begin : gen_comp2
    logic signed [VecBits-1:0] n1c, n2c, h1c, hec;
    assign n1c = n1_1[c*VecBits +: VecBits];
    assign n2c = n2_1[c*VecBits +: VecBits];
    assign h1c = h1_1[c*VecBits +: VecBits];
    assign hec = he_1[c*VecBits +: VecBits];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        dn_2[c]     <= (VecBits + 1)'(n2c) - (VecBits + 1)'(n1c);
        dh_2[c]     <= (VecBits + 1)'(hec) - (VecBits + 1)'(h1c);
        magn_2[c]   <= n1c[VecBits-1] ? VecBits'(-n1c) : VecBits'(n1c);
        magh_2[c]   <= h1c[VecBits-1] ? VecBits'(-h1c) : VecBits'(h1c);
        magn2_2[c]  <= n2c[VecBits-1] ? VecBits'(-n2c) : VecBits'(n2c);
        maghe_2[c]  <= hec[VecBits-1] ? VecBits'(-hec) : VecBits'(hec);
        sgnn_2[c]   <= n1c[VecBits-1];
        sgnh_2[c]   <= h1c[VecBits-1];
        hconst_2[c] <= AccBits'(h1c) <<< (LenBits - 1);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      k_2     <= k_c;
      l_2     <= l_c;
      zero_2  <= zero_c;
      n_2     <= n_1;
      len_2   <= len_1;
      scale_2 <= scale_1;
      tag_2   <= tag_1;
    end
  end

  // Steps: (N2 - N1) << k, sign-extended to AccBits (|N2 - N1| < 2^VecBits, k <= LenBits - 1).
  logic [3*AccBits-1:0] ea_2, eb_2, hc_2;
  for (genvar c = 0; c < 3; c++) begin : gen_step
    assign ea_2[c*AccBits +: AccBits] = (len_2 == '0) ? '0 : AccBits'(dn_2[c]) <<< k_2;
    assign eb_2[c*AccBits +: AccBits] = (len_2 == '0 || ConstH) ? '0 : AccBits'(dh_2[c]) <<< k_2;
    assign hc_2[c*AccBits +: AccBits] = hconst_2[c];
  end

  // ---- Headroom: the span's values scaled by 2^hn, 2^hb (exact: hn, hb are unused top bits) ----
  logic [VecBits-1:0]   magn_3 [3], magh_3 [3];
  logic [3*AccBits-1:0] ea_3, eb_3, hc_3;
  logic [LenBits-1:0]   l_3;
  logic [2:0]           sgnn_3, sgnh_3;
  logic                 zero_3;
  logic [NBits-1:0]     n_3;
  logic [LenBits-1:0]   len_3;
  logic [CBits-1:0]     scale_3;
  logic [TagBits-1:0]   tag_3;
  if (Headroom) begin : gen_headroom
    // VecBits - 1 - bit_width(x), 0 when x fills VecBits - 1 bits or more.
    function automatic logic [HBits-1:0] head(input logic [VecBits-1:0] x);
      head = HBits'(VecBits - 1);
      for (int b = 0; b < VecBits; b++) begin
        if (x[b]) head = (b >= VecBits - 1) ? '0 : HBits'(VecBits - 2 - b);
      end
    endfunction
    // Stage h1: hn, hb (OR of the magnitudes, priority encoders), the span's values beside;
    // stage h2: the shifts. Two stages, so that no stage holds an encoder and a shifter.
    logic [VecBits-1:0] orn, orh;
    always_comb begin
      orn = '0;
      orh = '0;
      for (int c = 0; c < 3; c++) begin
        orn = orn | magn_2[c] | magn2_2[c];
        orh = orh | magh_2[c] | (ConstH ? '0 : maghe_2[c]);
      end
    end
    logic [HBits-1:0]     hn_h, hb_h;
    logic [VecBits-1:0]   magn_h [3], magh_h [3];
    logic [3*AccBits-1:0] ea_h, eb_h, hc_h;
    logic [LenBits-1:0]   l_h;
    logic [2:0]           sgnn_h, sgnh_h;
    logic                 zero_h;
    logic [NBits-1:0]     n_h;
    logic [LenBits-1:0]   len_h;
    logic [CBits-1:0]     scale_h;
    logic [TagBits-1:0]   tag_h;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        hn_h    <= head(orn);
        hb_h    <= head(orh);
        for (int c = 0; c < 3; c++) begin
          magn_h[c] <= magn_2[c];
          magh_h[c] <= magh_2[c];
        end
        ea_h    <= ea_2;
        eb_h    <= eb_2;
        hc_h    <= hc_2;
        l_h     <= l_2;
        sgnn_h  <= sgnn_2;
        sgnh_h  <= sgnh_2;
        zero_h  <= zero_2;
        n_h     <= n_2;
        len_h   <= len_2;
        scale_h <= scale_2;
        tag_h   <= tag_2;
      end
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        for (int c = 0; c < 3; c++) begin
          magn_3[c] <= magn_h[c] << hn_h;
          magh_3[c] <= magh_h[c] << hb_h;
          ea_3[c*AccBits +: AccBits] <= ea_h[c*AccBits +: AccBits] << hn_h;
          eb_3[c*AccBits +: AccBits] <= eb_h[c*AccBits +: AccBits] << hb_h;
          hc_3[c*AccBits +: AccBits] <= hc_h[c*AccBits +: AccBits] << hb_h;
        end
        l_3     <= l_h;
        sgnn_3  <= sgnn_h;
        sgnh_3  <= sgnh_h;
        zero_3  <= zero_h;
        n_3     <= n_h;
        len_3   <= len_h;
        scale_3 <= scale_h;
        tag_3   <= tag_h;
      end
    end
  end else begin : gen_no_headroom
    logic unused_mag;
    assign unused_mag = ^{magn2_2[0], magn2_2[1], magn2_2[2], maghe_2[0], maghe_2[1], maghe_2[2]};
    for (genvar c = 0; c < 3; c++) begin : gen_mag3
      assign magn_3[c] = magn_2[c];
      assign magh_3[c] = magh_2[c];
    end
    assign ea_3    = ea_2;
    assign eb_3    = eb_2;
    assign hc_3    = hc_2;
    assign l_3     = l_2;
    assign sgnn_3  = sgnn_2;
    assign sgnh_3  = sgnh_2;
    assign zero_3  = zero_2;
    assign n_3     = n_2;
    assign len_3   = len_2;
    assign scale_3 = scale_2;
    assign tag_3   = tag_2;
  end

  // ---- the multipliers L * |N1|, L * |H1| (MulDepth stages); the steps and span values beside ----
  logic [LenBits+VecBits-1:0] pn_m [3], ph_m [3];
  for (genvar c = 0; c < 3; c++) begin : gen_mul
    phong_mul #(.ABits (LenBits), .BBits (VecBits), .TileBits (MulTileBits)) u_mul_n (
      .clk_i (clk_i), .en_i (en_i), .a_i (l_3), .b_i (magn_3[c]), .p_o (pn_m[c]));
    if (ConstH) begin : gen_const_h
      logic unused_magh;
      assign unused_magh = ^magh_3[c];
      assign ph_m[c] = '0;
    end else begin : gen_var_h
      phong_mul #(.ABits (LenBits), .BBits (VecBits), .TileBits (MulTileBits)) u_mul_h (
        .clk_i (clk_i), .en_i (en_i), .a_i (l_3), .b_i (magh_3[c]), .p_o (ph_m[c]));
    end
  end

  logic [3*AccBits-1:0] ea_m, eb_m, hc_m;
  logic [2:0] sgnn_m, sgnh_m;
  logic       zero_m;
  logic [NBits-1:0]   n_m;
  logic [LenBits-1:0] len_m;
  logic [CBits-1:0]   scale_m;
  logic [TagBits-1:0] tag_m;
  specular_delay #(.Width (9 * AccBits + 6 + 1 + NBits + LenBits + CBits + TagBits), .Depth (MulDepth),
                   .Reset (1'b0)) u_side (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i),
    .d_i   ({ea_3, eb_3, hc_3, sgnn_3, sgnh_3, zero_3, n_3, len_3, scale_3, tag_3}),
    .q_o   ({ea_m, eb_m, hc_m, sgnn_m, sgnh_m, zero_m, n_m, len_m, scale_m, tag_m}));

  // ---- last stage: signs and rounding, one adder each: +-P + Round = (P ^ s) + (Round + s) ----
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      for (int c = 0; c < 3; c++) begin
        a0_o[c*AccBits +: AccBits] <= (AccBits'(pn_m[c]) ^ {AccBits{sgnn_m[c]}}) + (Round + AccBits'(sgnn_m[c]));
        b0_o[c*AccBits +: AccBits] <= ConstH ? hc_m[c*AccBits +: AccBits] + Round
                                             : (AccBits'(ph_m[c]) ^ {AccBits{sgnh_m[c]}}) + (Round + AccBits'(sgnh_m[c]));
      end
      ea_o    <= ea_m;
      eb_o    <= eb_m;
      zero_o  <= zero_m;
      n_o     <= n_m;
      len_o   <= len_m;
      scale_o <= scale_m;
      tag_o   <= tag_m;
    end
  end

endmodule
