// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// fpga_ooc: the out-of-context place-and-route harness (registered IO, five pins: clk_i,
// rst_ni, sdi_i, load_i, xor_o) around one top level of the core, chosen by Top (0 unit,
// 1 stream, 2 axil; 3 phong: phong_stream, the per-pixel Blinn-Phong competitor of
// docs/phong_hw.md; 4 setup: specular_setup, the scanline setup in hardware, and 5 system:
// specular_system, setup then stream, docs/setup_hw.md; 6 mul: specular_pipe_mul alone). See
// fpga_ooc_io.sv for the pins and rtl/fpga/README.md for the flow (scripts/fpga.py). Not
// part of the device.
//
// Input word (InBits bits, shifted in msb first, applied on load_i), from the msb down;
// the loaded word stays applied until the next load (strobes, valids and readies are
// levels here):
//   unit    c_we, c[CBits], dpsi_we, dpsi[AngleBits], psi0_we, psi0[AngleBits], n_we,
//           n[NBits], len_we, len[LenBits], start
//   stream  span_valid, c[Channels*CBits], psi0[AngleBits], dpsi[AngleBits], n[NBits],
//           len[LenBits], tag[TagBits], px_ready
//   axil    awvalid, awaddr[AddrWidth], awprot[3], wvalid, wdata[32], wstrb[4], bready,
//           arvalid, araddr[AddrWidth], arprot[3], rready, m_axis_px_tready
//   phong   geo_valid, n1, n2, h1, he [3*VecBits each], n[NBits], len[LenBits],
//           scale[CBits], tag[TagBits], px_ready
//   setup   geo_valid, n1, n2, h1, he [3*VecBits each], n[NBits], len[LenBits],
//           scale[CBits], tag[TagBits], span_ready
//   system  as phong (the last bit px_ready)
//   mul     a[MulBits], b[MulBits]: specular_pipe_mul alone (6 mul; the flow's smoke test)
// Output parity, over:
//   unit    intensity_o, valid_o, busy_o
//   stream  span_ready_o, px_valid_o, px_intensity_o, px_last_o, px_tag_o
//   axil    awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid,
//           m_axis_px_tdata, m_axis_px_tvalid, m_axis_px_tlast, m_axis_px_tuser, irq_o
//   phong   geo_ready_o, px_valid_o, px_intensity_o, px_last_o, px_tag_o
//   setup   geo_ready_o, span_valid_o, span_c_o, span_psi0_o, span_dpsi_o, span_n_o,
//           span_len_o, span_tag_o, span_status_o
//   system  as phong
//   mul     p_o of specular_pipe_mul
//
// Parameters: the interface widths are passed through to the core (TagBits to the stream
// and the AXI4-Lite core, AddrWidth to the latter only; specular_axil's registers are 32
// bits wide whatever AngleBits, NBits and LenBits); Channels (the core's C values per span,
// rtl/core/specular_params.svh) widens the stream's C and intensity and goes to the unit,
// the stream, the AXI4-Lite core and the system (which refuse all but 1 themselves). Every other core parameter (ROM files,
// CosAddrBits, ...) keeps the core's own default unless scripts/fpga.py sets it on the
// core module by name (chparam), so a changed default in rtl/ is never shadowed by a stale
// copy here.

`include "specular_assert.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"
`include "specular_axil_ports.svh"

module fpga_ooc #(
  parameter int Top       = 1,   // the core: 0 specular_unit, 1 specular_stream, 2 specular_axil,
                                 // 3 phong_stream, 4 specular_setup, 5 specular_system,
                                 // 6 specular_pipe_mul
  parameter int CBits     = 16,
  parameter int Channels  = 1,   // the core's Channels: C values per span (1, or 3 for RGB)
  parameter int AngleBits = 32,
  parameter int NBits     = 10,
  parameter int LenBits   = 11,
  parameter int TagBits   = 16,
  parameter int AddrWidth = 8,
  parameter int VecBits   = 18,  // phong_stream's vector components
  parameter int MulBits   = 16   // Top 6: the operand width of the lone multiplier
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  input  logic load_i,
  output logic xor_o
);

  localparam int TopUnit   = 0;
  localparam int TopStream = 1;
  localparam int TopAxil   = 2;
  localparam int TopPhong  = 3;
  localparam int TopSetup  = 4;
  localparam int TopSystem = 5;
  localparam int TopMul    = 6;  // specular_pipe_mul alone: the smallest block, for the flow's smoke test

  localparam int PxBits  = ((CBits + 7) / 8) * 8;   // AXI4-Stream TDATA: whole bytes
  localparam int InBits  = (Top == TopUnit)   ? 5 + CBits + 2 * AngleBits + NBits + LenBits + 1
                         : (Top == TopStream) ? 2 + Channels * CBits + 2 * AngleBits + NBits + LenBits + TagBits
                         : (Top == TopPhong || Top == TopSetup || Top == TopSystem)
                                              ? 2 + `SPECULAR_GEO_DATA_BITS
                         : (Top == TopMul)    ? 2 * MulBits
                         :                     2 * AddrWidth + 48;
  localparam int OutBits = (Top == TopUnit)   ? CBits + 2
                         : (Top == TopStream) ? 3 + Channels * CBits + TagBits
                         : (Top == TopPhong || Top == TopSystem)
                                              ? 3 + CBits + TagBits
                         : (Top == TopSetup)  ? 2 + CBits + 2 * AngleBits + NBits + LenBits + TagBits + 3
                         : (Top == TopMul)    ? 2 * MulBits
                         :                     41 + PxBits + 3 + TagBits;

  // Channels reaches the cores that have it; the others have one C.
  if (Channels != 1 && (Top == TopPhong || Top == TopSetup || Top == TopMul)) begin : gen_channels_check
    `SPEC_PARAM_ERROR("fpga_ooc: Channels applies to the unit, stream, axil and system tops only")
  end

  logic               core_rst_n;
  logic [InBits-1:0]  core_in;
  logic [OutBits-1:0] core_out;

  fpga_ooc_io #(
    .InBits  (InBits),
    .OutBits (OutBits)
  ) u_io (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .sdi_i       (sdi_i),
    .load_i      (load_i),
    .xor_o       (xor_o),
    .core_rst_no (core_rst_n),
    .core_in_o   (core_in),
    .core_out_i  (core_out)
  );

  if (Top == TopUnit) begin : gen_unit
    logic                 c_we, dpsi_we, psi0_we, n_we, len_we, start;
    logic [CBits-1:0]     c, intensity;
    logic [AngleBits-1:0] dpsi, psi0;
    logic [NBits-1:0]     n;
    logic [LenBits-1:0]   len;
    logic                 valid, busy;

    assign {c_we, c, dpsi_we, dpsi, psi0_we, psi0, n_we, n, len_we, len, start} = core_in;
    assign core_out = {intensity, valid, busy};

    specular_unit #(
      .CBits     (CBits),
      .Channels  (Channels),
      .AngleBits (AngleBits),
      .NBits     (NBits),
      .LenBits   (LenBits)
    ) u_core (
      .clk_i       (clk_i),
      .rst_ni      (core_rst_n),
      .c_we_i      (c_we),
      .c_i         (c),
      .dpsi_we_i   (dpsi_we),
      .dpsi_i      (dpsi),
      .psi0_we_i   (psi0_we),
      .psi0_i      (psi0),
      .n_we_i      (n_we),
      .n_i         (n),
      .len_we_i    (len_we),
      .len_i       (len),
      .start_i     (start),
      .intensity_o (intensity),
      .valid_o     (valid),
      .busy_o      (busy)
    );
  end else if (Top == TopStream) begin : gen_stream
    logic                 span_valid, span_ready, px_valid, px_ready, px_last;
    logic [Channels*CBits-1:0] span_c, px_intensity;
    logic [AngleBits-1:0] span_psi0, span_dpsi;
    logic [NBits-1:0]     span_n;
    logic [LenBits-1:0]   span_len;
    logic [TagBits-1:0]   span_tag, px_tag;

    assign {span_valid, `SPECULAR_SPAN_DATA(span_, ), px_ready} = core_in;
    assign core_out = {span_ready, px_valid, px_intensity, px_last, px_tag};

    specular_stream #(
      .CBits     (CBits),
      .Channels  (Channels),
      .AngleBits (AngleBits),
      .NBits     (NBits),
      .LenBits   (LenBits),
      .TagBits   (TagBits)
    ) u_core (
      .clk_i          (clk_i),
      .rst_ni         (core_rst_n),
      `SPECULAR_SPAN_MAP(_i, _o, span_, , ),
      `SPECULAR_PX_MAP(px_, , )
    );
  end else if (Top == TopAxil) begin : gen_axil
    logic                 awvalid, awready, wvalid, wready, bvalid, bready;
    logic                 arvalid, arready, rvalid, rready;
    logic [AddrWidth-1:0] awaddr, araddr;
    logic [2:0]           awprot, arprot;
    logic [31:0]          wdata, rdata;
    logic [3:0]           wstrb;
    logic [1:0]           bresp, rresp;
    logic [PxBits-1:0]    px_tdata;
    logic                 px_tvalid, px_tready, px_tlast, irq;
    logic [TagBits-1:0]   px_tuser;

    assign {awvalid, awaddr, awprot, wvalid, wdata, wstrb, bready,
            arvalid, araddr, arprot, rready, px_tready} = core_in;
    assign core_out = {awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid,
                       px_tdata, px_tvalid, px_tlast, px_tuser, irq};

    specular_axil #(
      .CBits     (CBits),
      .Channels  (Channels),
      .AngleBits (AngleBits),
      .NBits     (NBits),
      .LenBits   (LenBits),
      .TagBits   (TagBits),
      .AddrWidth (AddrWidth)
    ) u_core (
      .clk_i            (clk_i),
      .rst_ni           (core_rst_n),
      `SPECULAR_AXIL_MAP(),
      `SPECULAR_AXIS_PX_MAP(px_),
      .irq_o            (irq)
    );
  end else if (Top == TopPhong || Top == TopSetup || Top == TopSystem) begin : gen_geo
    // The geometry span side (rtl/prim/specular_geo_ports.svh), then the ready of the
    // core's output side (px_ready or span_ready).
    logic                 geo_valid, geo_ready, out_ready;
    logic [3*VecBits-1:0] geo_n1, geo_n2, geo_h1, geo_he;
    logic [NBits-1:0]     geo_n;
    logic [LenBits-1:0]   geo_len;
    logic [CBits-1:0]     geo_scale;
    logic [TagBits-1:0]   geo_tag;

    assign {geo_valid, `SPECULAR_GEO_DATA(geo_, ), out_ready} = core_in;

    if (Top == TopSetup) begin : gen_setup
      logic                 span_valid;
      logic [NBits-1:0]     span_n;
      logic [LenBits-1:0]   span_len;
      logic [CBits-1:0]     span_c;
      logic [AngleBits-1:0] span_psi0, span_dpsi;
      logic [TagBits-1:0]   span_tag;
      logic [2:0]           span_status;

      assign core_out = {geo_ready, span_valid, span_c, span_psi0, span_dpsi, span_n, span_len,
                         span_tag, span_status};

      // specular_setup's register widths are fixed (C 16, angles 32, n 10, l 11): with other
      // CBits, AngleBits, NBits or LenBits the port widths differ and elaboration says so.
      // Its other parameters (TileBits, SetupII, the ROM files) keep their defaults unless the
      // flow sets them by name (chparam).
      specular_setup #(
        .VecBits (VecBits),
        .TagBits (TagBits)
      ) u_core (
        .clk_i         (clk_i),
        .rst_ni        (core_rst_n),
        `SPECULAR_GEO_MAP(geo_, , ),
        .span_valid_o  (span_valid),
        .span_ready_i  (out_ready),
        .span_c_o      (span_c),
        .span_psi0_o   (span_psi0),
        .span_dpsi_o   (span_dpsi),
        .span_n_o      (span_n),
        .span_len_o    (span_len),
        .span_tag_o    (span_tag),
        .span_status_o (span_status)
      );
    end else begin : gen_px
      logic               px_valid, px_ready, px_last;
      logic [CBits-1:0]   px_intensity;
      logic [TagBits-1:0] px_tag;

      assign px_ready = out_ready;
      assign core_out = {geo_ready, px_valid, px_intensity, px_last, px_tag};

      if (Top == TopPhong) begin : gen_phong
        phong_stream #(
          .VecBits (VecBits),
          .LenBits (LenBits),
          .NBits   (NBits),
          .CBits   (CBits),
          .TagBits (TagBits)
        ) u_core (
          .clk_i          (clk_i),
          .rst_ni         (core_rst_n),
          `SPECULAR_GEO_MAP(geo_, , ),
          `SPECULAR_PX_MAP(px_, , )
        );
      end else begin : gen_system
        specular_system #(
          .CBits     (CBits),
          .Channels  (Channels),
          .AngleBits (AngleBits),
          .NBits     (NBits),
          .LenBits   (LenBits),
          .TagBits   (TagBits),
          .VecBits   (VecBits)
        ) u_core (
          .clk_i          (clk_i),
          .rst_ni         (core_rst_n),
          `SPECULAR_GEO_MAP(geo_, , ),
          `SPECULAR_PX_MAP(px_, , )
        );
      end
    end
  end else if (Top == TopMul) begin : gen_mul
    logic [MulBits-1:0] a, b, a_q, b_q;
    logic [MulBits+1:0] a3_q;

    logic unused_rst_n;  // the multiplier has no reset: its datapath carries no state

    assign {a, b} = core_in;
    assign unused_rst_n = core_rst_n;
    // The caller's 3a, registered in front of the tree as multiplier 11 does.
    always_ff @(posedge clk_i) begin
      a_q  <= a;
      a3_q <= (MulBits + 2)'(a) + ((MulBits + 2)'(a) << 1);
      b_q  <= b;
    end

    specular_pipe_mul #(
      .ABits (MulBits),
      .BBits (MulBits)
    ) u_core (
      .clk_i (clk_i),
      .en_i  (1'b1),
      .a_i   (a_q),
      .a3_i  (a3_q),
      .b_i   (b_q),
      .p_o   (core_out)
    );
  end else begin : gen_top_check
    `SPEC_PARAM_ERROR("fpga_ooc: Top must be 0 (unit), 1 (stream), 2 (axil), 3 (phong), 4 (setup), 5 (system) or 6 (mul)")
  end

endmodule
