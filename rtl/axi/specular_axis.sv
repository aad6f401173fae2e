// SPDX-License-Identifier: Apache-2.0
//
// specular_axis: specular_stream with AXI4-Stream ports. Packing and renaming only: no
// register, no logic; every handshake rule, the latency and the pixel values are those of
// specular_stream (rtl/core/specular_stream.sv, docs/interfaces.md).
//
// Span side (slave), one transfer per span descriptor:
//   s_axis_span_tdata[SpanDataBits]  {len, n, dpsi, psi0, c}, c in the least significant
//                                    bits, zero-padded to a whole number of bytes (the pad
//                                    bits are ignored); c is Channels * CBits wide (channel
//                                    0 lowest), the fields above it move up by as much.
//                                    Default widths (104 bits, 13 bytes):
//                                      [15:0]   c     CBits
//                                      [47:16]  psi0  AngleBits
//                                      [79:48]  dpsi  AngleBits
//                                      [89:80]  n     NBits
//                                      [100:90] len   LenBits (the span has len + 1 pixels)
//                                      [103:101] pad
//   s_axis_span_tuser[TagBits]       the span's tag (span_tag_i)
//   s_axis_span_tvalid, s_axis_span_tready
// Pixel side (master), one transfer per pixel:
//   m_axis_px_tdata[PxDataBits]      the intensity (Channels * CBits, channel 0 lowest)
//                                    zero-extended to a whole number of bytes (16 bits with
//                                    the defaults, 48 with Channels = 3)
//   m_axis_px_tlast                  last pixel of its span (pixel len)
//   m_axis_px_tuser[TagBits]         its span's tag
//   m_axis_px_tvalid, m_axis_px_tready
// No TKEEP/TSTRB (every byte is a data byte), TID or TDEST.
//
// Parameters: those of specular_stream (the core's list, rtl/core/specular_params.svh, and
// TagBits), passed through; the TDATA widths follow from them. s_axis_span_tready
// depends on registers only (never on s_axis_span_tvalid or m_axis_px_tready), as
// specular_stream's span_ready_o.

`include "specular_params.svh"
`include "specular_axil_ports.svh"

module specular_axis #(
  `SPECULAR_CORE_PARAMS,
  parameter int TagBits /*verilator public*/     = 16
) (
  input  logic clk_i,
  input  logic rst_ni,

  input  logic [((Channels * CBits + 2 * AngleBits + NBits + LenBits + 7) / 8) * 8-1:0] s_axis_span_tdata,
  input  logic [TagBits-1:0] s_axis_span_tuser,
  input  logic               s_axis_span_tvalid,
  output logic               s_axis_span_tready,

  `SPECULAR_AXIS_PX_PORTS
);

  // Descriptor layout: bit offsets of each field in s_axis_span_tdata (read by testbenches).
  localparam int CAllBits                        = Channels * CBits;  // c: every channel
  localparam int SpanBits                        = CAllBits + 2 * AngleBits + NBits + LenBits;
  localparam int SpanDataBits /*verilator public*/ = ((SpanBits + 7) / 8) * 8;
  localparam int PxDataBits /*verilator public*/   = ((CAllBits + 7) / 8) * 8;
  localparam int OffC /*verilator public*/         = 0;
  localparam int OffPsi0 /*verilator public*/      = OffC + CAllBits;
  localparam int OffDpsi /*verilator public*/      = OffPsi0 + AngleBits;
  localparam int OffN /*verilator public*/         = OffDpsi + AngleBits;
  localparam int OffLen /*verilator public*/       = OffN + NBits;

  logic [CAllBits-1:0]  span_c, px_intensity;
  logic [AngleBits-1:0] span_psi0, span_dpsi;
  logic [NBits-1:0]     span_n;
  logic [LenBits-1:0]   span_len;

  assign span_c    = s_axis_span_tdata[OffC +: CAllBits];
  assign span_psi0 = s_axis_span_tdata[OffPsi0 +: AngleBits];
  assign span_dpsi = s_axis_span_tdata[OffDpsi +: AngleBits];
  assign span_n    = s_axis_span_tdata[OffN +: NBits];
  assign span_len  = s_axis_span_tdata[OffLen +: LenBits];

  if (SpanDataBits > SpanBits) begin : gen_span_pad
    logic unused_pad;
    assign unused_pad = ^s_axis_span_tdata[SpanDataBits-1:SpanBits];
  end

  specular_stream #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits      (TagBits)
  ) u_stream (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .span_valid_i   (s_axis_span_tvalid),
    .span_ready_o   (s_axis_span_tready),
    .span_c_i       (span_c),
    .span_psi0_i    (span_psi0),
    .span_dpsi_i    (span_dpsi),
    .span_n_i       (span_n),
    .span_len_i     (span_len),
    .span_tag_i     (s_axis_span_tuser),
    .px_valid_o     (m_axis_px_tvalid),
    .px_ready_i     (m_axis_px_tready),
    .px_intensity_o (px_intensity),
    .px_last_o      (m_axis_px_tlast),
    .px_tag_o       (m_axis_px_tuser)
  );

  assign m_axis_px_tdata = PxDataBits'(px_intensity);  // zero-extended

endmodule
