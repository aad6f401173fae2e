// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// phong_stream: per-pixel Blinn-Phong shading on the geometry span interface
// (docs/interfaces.md#geometry-span-interface), the competitor of the device in hardware
// (docs/phong_hw.md). For span (N1, N2, H1, He, n, l, scale, tag) pixel i = 0..l is
//   I_i = scale * max(0, N_i . H_i / (|N_i| |H_i|))^n,
//   N_i = N1 + (N2 - N1) i / l,  H_i = H1 + (He - H1) i / l,
// bit-identical to model/device/phong_model.hpp (PhongFormat: the parameters below have its
// fields' names and defaults; the cross form's fields those of PhongFormat::cross()).
// Cross = 0: the textbook form, c = N.H / sqrt(|N|^2 |H|^2) and w = -log2 c (phong_norm,
// phong_log2); Cross = 1: the cancellation-free form, w from sin^2 or cos^2 (phong_cross,
// docs/phong_hw.md#the-cancellation-free-form). Both: 2^-nw and the scale (phong_exp2).
//
// Ports: clk_i, rst_ni (asynchronous, active low: drops every span and pixel in flight);
// the span side geo_* (AXI4-Stream rules); the pixel side px_* of specular_stream.
// geo_ready_o depends on registers only: it is high when the span pipe advances at the next
// edge (the output buffer has room and the span pipe's head is empty or taken).
//
// Pipeline (one carry chain per stage, every stage register enabled by adv, the output
// buffer's registered room; the span pipe by the same adv and its own head):
//   span pipe      phong_span_setup: L = l 2^k, A0 = L N1, steps (N2 - N1) 2^k, the same for H
//   stage 0        the lerp accumulators A_i = A0 + i EA, B_i (control unit: specular_control,
//                  pixel counter: specular_down_counter), the span's n, scale, zero flag, tag
//   then           phong_dot (a.b, |a|^2, |b|^2; a x b with Cross), phong_norm (c) and phong_log2
//                  (w = -log2 c) or with Cross phong_cross (w), then phong_exp2 (scale 2^-nw)
//   output buffer  specular_out_buf
// Stage counts: phong_pkg (docs/phong_hw.md#pipeline). One pixel per clock sustained, l = 0
// spans back to back included: the control takes the span pipe's head on the edge at which
// the previous span's last pixel leaves stage 0.

`include "specular_assert.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module phong_stream #(
  parameter int VecBits       = 18,
  parameter int LenBits       = 11,
  parameter int NBits         = 10,
  parameter int CBits         = 16,
  parameter int TagBits       = 16,
  parameter bit ConstH        = 1'b0,
  parameter int OpBits        = 20,
  parameter int NormBits      = 24,
  parameter int RsqrtAddrBits = 6,
  parameter int Newton        = 2,
  parameter int CosFrac       = 23,
  parameter int LogAddrBits   = 9,
  parameter int LogFracBits   = 13,
  parameter int LogBits       = 21,
  parameter int ExpAddrBits   = 5,
  parameter int ExpFracBits   = 7,
  parameter int ExpBits       = 16,
  parameter     RsqrtRomFile  = "roms/phong/n1000/rsqrt.hex",
  parameter     LogRomFile    = "roms/phong/n1000/log2.hex",
  parameter     ExpRomFile    = "roms/phong/n1000/exp2.hex",
  // The cancellation-free form (Cross = 1); unused otherwise.
  parameter bit Cross         = 1'b0,
  parameter int UBits         = 20,
  parameter int RcpAddrBits   = 7,
  parameter int RcpFracBits   = 8,
  parameter int RcpBits       = 17,
  parameter int SFrac         = 24,
  parameter int GAddrBits     = 5,
  parameter int GFracBits     = 8,
  parameter int GBits         = 17,
  parameter int DmFrac        = 14,
  parameter     RcpRomFile    = "roms/phong/cross_n1000/rcp.hex",
  parameter     GRomFile      = "roms/phong/cross_n1000/g.hex",
  // The multipliers' resources (phong_mul's TileBits): 0 LUT trees (iCE40-HX8K), 16
  // SB_MAC16 tiles (UP5K), 18 MULT18X18D tiles (ECP5); bit-exact and of one latency
  // (docs/pipeline.md#multiplier-styles), so no stage count depends on it.
  parameter int MulTileBits   = 0
) (
  input  logic                   clk_i,
  input  logic                   rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_PX_PORTS
);

  localparam int AccBits   = VecBits + LenBits;
  localparam int WBits     = Cross ? phong_pkg::cross_w_bits(OpBits, LogBits) : $clog2(CosFrac + 2) + LogBits;
  localparam int DotStages = phong_pkg::dot_stages(OpBits);
  // The stages from the dot products to w (phong_norm and phong_log2, or phong_cross) and the
  // pipeline.
  localparam int ToWStages = Cross ? phong_pkg::cross_stages(NormBits, RcpFracBits, UBits, RcpBits, GFracBits,
                                                             LogFracBits, GBits)
                                   : phong_pkg::norm_stages(NormBits, Newton) + phong_pkg::log2_stages(LogFracBits);
  localparam int PipeDepth = phong_pkg::pipe_depth(OpBits, ToWStages,
                                                    phong_pkg::exp2_stages(WBits, ExpFracBits, ExpBits));

  if (NBits != 10 || TagBits < 1 || OpBits > AccBits) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_stream: NBits must be 10, TagBits >= 1, OpBits <= VecBits + LenBits")
  end

  // ---------------------------------------------------------------------------------
  // Span pipe
  // ---------------------------------------------------------------------------------
  logic adv, sp_adv, head_valid, ctrl_ready, accept;
  logic [3*AccBits-1:0] a0_h, ea_h, b0_h, eb_h;
  logic [NBits-1:0]     n_h;
  logic [LenBits-1:0]   len_h;
  logic [CBits-1:0]     scale_h;
  logic [TagBits-1:0]   tag_h;
  logic                 zero_h;

  assign sp_adv      = ctrl_ready | (adv & ~head_valid);
  assign geo_ready_o = sp_adv;

  phong_span_setup #(
    .VecBits (VecBits),
    .LenBits (LenBits),
    .NBits   (NBits),
    .CBits   (CBits),
    .TagBits (TagBits),
    .ConstH  (ConstH),
    .Headroom  (Cross),
    .RoundBits (Cross ? AccBits - OpBits : 0),
    .MulTileBits (MulTileBits)
  ) u_setup (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .en_i    (sp_adv),
    .valid_i (geo_valid_i),
    .n1_i    (geo_n1_i),
    .n2_i    (geo_n2_i),
    .h1_i    (geo_h1_i),
    .he_i    (geo_he_i),
    .n_i     (geo_n_i),
    .len_i   (geo_len_i),
    .scale_i (geo_scale_i),
    .tag_i   (geo_tag_i),
    .valid_o (head_valid),
    .a0_o    (a0_h),
    .ea_o    (ea_h),
    .b0_o    (b0_h),
    .eb_o    (eb_h),
    .n_o     (n_h),
    .len_o   (len_h),
    .scale_o (scale_h),
    .tag_o   (tag_h),
    .zero_o  (zero_h)
  );

  // ---------------------------------------------------------------------------------
  // Control unit and stage 0: the accumulators
  // ---------------------------------------------------------------------------------
  logic mux_sel, count, cnt_zero, out_valid, out_last, unused_strobe, unused_busy;
  logic [PipeDepth-1:0] stage_valid;
  logic unused_borrow;
  logic [LenBits-1:0] unused_cnt;

  specular_control #(
    .PipeDepth (PipeDepth)
  ) u_control (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .span_valid_i  (head_valid),
    .span_ready_o  (ctrl_ready),
    .adv_i         (adv),
    .cnt_zero_i    (cnt_zero),
    .accept_o      (accept),
    .strobe_o      (unused_strobe),
    .sel_o         (mux_sel),
    .count_o       (count),
    .stage_valid_o (stage_valid),
    .out_valid_o   (out_valid),
    .out_last_o    (out_last),
    .busy_o        (unused_busy)
  );

  specular_down_counter #(.LenBits (LenBits)) u_counter (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .len_we_i (accept),
    .len_i    (len_h),
    .count_i  (count),
    .borrow_o (unused_borrow),
    .zero_o   (cnt_zero),
    .count_o  (unused_cnt)
  );

  // A_i, B_i: A0 on accept, else A + EA at every advance (a bubble's value is not used).
  logic [3*AccBits-1:0] a_q, b_q, ea_q, eb_q;
  logic [NBits-1:0]     n0;
  logic [CBits-1:0]     scale0;
  logic [TagBits-1:0]   tag0;
  logic                 zero0;
  always_ff @(posedge clk_i) begin
    if (accept) begin
      ea_q   <= ea_h;
      eb_q   <= eb_h;
      n0     <= n_h;
      scale0 <= scale_h;
      tag0   <= tag_h;
      zero0  <= zero_h;
    end
  end
  for (genvar c = 0; c < 3; c++) begin : gen_acc
    always_ff @(posedge clk_i) begin
      if (adv) begin
        a_q[c*AccBits +: AccBits] <= mux_sel ? a_q[c*AccBits +: AccBits] + ea_q[c*AccBits +: AccBits]
                                             : a0_h[c*AccBits +: AccBits];
        b_q[c*AccBits +: AccBits] <= mux_sel ? b_q[c*AccBits +: AccBits] + eb_q[c*AccBits +: AccBits]
                                             : b0_h[c*AccBits +: AccBits];
      end
    end
  end

  // ---------------------------------------------------------------------------------
  // Datapath
  // ---------------------------------------------------------------------------------
  logic signed [2*OpBits+1:0] d;
  logic [2*OpBits-1:0]        na, nb;
  logic [3*(2*OpBits+1)-1:0] u;
  phong_dot #(.AccBits (AccBits), .OpBits (OpBits), .Cross (Cross), .MulTileBits (MulTileBits)) u_dot (
    .clk_i (clk_i), .en_i (adv), .a_i (a_q), .b_i (b_q), .d_o (d), .na_o (na), .nb_o (nb), .u_o (u));

  // w = -log2 c and the zero flag of the form.
  logic [WBits-1:0] w;
  logic             zero_w;
  if (Cross) begin : gen_cross
    phong_cross #(
      .OpBits      (OpBits),
      .NormBits    (NormBits),
      .UBits       (UBits),
      .RcpAddrBits (RcpAddrBits),
      .RcpFracBits (RcpFracBits),
      .RcpBits     (RcpBits),
      .SFrac       (SFrac),
      .GAddrBits   (GAddrBits),
      .GFracBits   (GFracBits),
      .GBits       (GBits),
      .DmFrac      (DmFrac),
      .CosFrac     (CosFrac),
      .LogAddrBits (LogAddrBits),
      .LogFracBits (LogFracBits),
      .LogBits     (LogBits),
      .RcpRomFile  (RcpRomFile),
      .GRomFile    (GRomFile),
      .LogRomFile  (LogRomFile),
      .MulTileBits (MulTileBits)
    ) u_cross (
      .clk_i  (clk_i),
      .en_i   (adv),
      .d_i    (d),
      .na_i   (na),
      .nb_i   (nb),
      .u_i    (u),
      .w_o    (w),
      .zero_o (zero_w)
    );
  end else begin : gen_dot
    logic unused_u;
    assign unused_u = ^u;
    logic [CosFrac:0] cosv;
    logic             zero_c;
    phong_norm #(
      .OpBits        (OpBits),
      .NormBits      (NormBits),
      .RsqrtAddrBits (RsqrtAddrBits),
      .Newton        (Newton),
      .CosFrac       (CosFrac),
      .RsqrtRomFile  (RsqrtRomFile),
      .MulTileBits   (MulTileBits)
    ) u_norm (
      .clk_i  (clk_i),
      .en_i   (adv),
      .d_i    (d),
      .na_i   (na),
      .nb_i   (nb),
      .c_o    (cosv),
      .zero_o (zero_c)
    );
    phong_log2 #(
      .CosFrac     (CosFrac),
      .LogAddrBits (LogAddrBits),
      .LogFracBits (LogFracBits),
      .LogBits     (LogBits),
      .LogRomFile  (LogRomFile),
      .MulTileBits (MulTileBits)
    ) u_log2 (
      .clk_i (clk_i),
      .en_i  (adv),
      .c_i   (cosv),
      .w_o   (w)
    );
    specular_delay #(.Width (1), .Depth (phong_pkg::log2_stages(LogFracBits)), .Reset (1'b0)) u_zero_line (
      .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (zero_c), .q_o (zero_w));
  end

  // The span's n, scale and zero flag beside the pixel up to w; the tag to the end.
  logic [NBits-1:0]   n_p;
  logic [CBits-1:0]   scale_p;
  logic               zero_p;
  logic [TagBits-1:0] tag_out;
  logic [CBits-1:0]   intensity;
  specular_delay #(.Width (NBits + CBits + 1), .Depth (DotStages + ToWStages), .Reset (1'b0)) u_span_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i ({n0, scale0, zero0}), .q_o ({n_p, scale_p, zero_p}));
  specular_delay #(.Width (TagBits), .Depth (PipeDepth - 1)) u_tag_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (tag0), .q_o (tag_out));

  // The power and the scale (both forms).
  phong_exp2 #(
    .WBits       (WBits),
    .LogBits     (LogBits),
    .ExpAddrBits (ExpAddrBits),
    .ExpFracBits (ExpFracBits),
    .ExpBits     (ExpBits),
    .NBits       (NBits),
    .CBits       (CBits),
    .ExpRomFile  (ExpRomFile),
    .MulTileBits (MulTileBits)
  ) u_exp2 (
    .clk_i       (clk_i),
    .en_i        (adv),
    .w_i         (w),
    .zero_i      (zero_w | zero_p),
    .n_i         (n_p),
    .scale_i     (scale_p),
    .intensity_o (intensity)
  );

  // ---------------------------------------------------------------------------------
  // Output buffer
  // ---------------------------------------------------------------------------------
  logic [CBits-1:0] intensity_v;
  assign intensity_v = out_valid ? intensity : '0;
  logic unused_adv_d;
  specular_out_buf #(
    .Width (CBits + 1 + TagBits)
  ) u_out_buf (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .adv_o      (adv),
    .adv_d_o    (unused_adv_d),  // the advance is adv_o itself here
    .in_valid_i (out_valid),
    .in_data_i  ({intensity_v, out_last, tag_out}),
    .px_valid_o (px_valid_o),
    .px_ready_i (px_ready_i),
    .px_data_o  ({px_intensity_o, px_last_o, px_tag_o})
  );

  // ---------------------------------------------------------------------------------
  // Assertions (rtl/prim/specular_assert.svh)
  // ---------------------------------------------------------------------------------
  `SPEC_ASSERT_KNOWN(GeoValidKnown_A, geo_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(GeoKnown_A, `SPECULAR_GEO_DATA(geo_, _i), geo_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(PxReadyKnown_A, px_ready_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(PxKnown_A, {px_intensity_o, px_last_o, px_tag_o}, px_valid_o, clk_i, rst_ni)

`ifndef SYNTHESIS
  // Pixels owed: l + 1 per accepted span (at the span pipe's input), minus one per transfer.
  localparam int OweBits = LenBits + 8;
  logic [OweBits-1:0] owed_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      owed_q <= '0;
    end else begin
      owed_q <= owed_q
                + ((geo_valid_i && geo_ready_o) ? OweBits'(geo_len_i) + OweBits'(1) : '0)
                - ((px_valid_o && px_ready_i) ? OweBits'(1) : '0);
    end
  end
  `SPEC_ASSERT_IF(PxOwed_A, px_valid_o, owed_q != '0, clk_i, rst_ni)
  `SPEC_ASSERT_IF(NoneOwedEmpty_A, owed_q == '0, stage_valid == '0 && !head_valid, clk_i, rst_ni)
`endif

endmodule
