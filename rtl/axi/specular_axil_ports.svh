// SPDX-License-Identifier: Apache-2.0
//
// The AXI4-Lite slave port of specular_axil
// (docs/interfaces.md#axi4-lite-register-interface-specular_axil), written once for the module, its formal harness (rtl/axi/formal/specular_axil_fv.sv) and
// the out-of-context harness (rtl/fpga/fpga_ooc.sv). A module that uses these macros names
// its address width AddrWidth; the data is 32 bits.
//
//   `SPECULAR_AXIL_PORTS    the declarations s_axil_awaddr .. s_axil_rready; no comma at
//                           either end
//   `SPECULAR_AXIL_MAP(P)   their named connections to P``awaddr .. P``rready: s_axil_ maps
//                           them through, an empty P to local signals awaddr, ...
//
// The AXI4-Stream pixel master of specular_axis and specular_axil
// (docs/interfaces.md#axi4-stream-wrapper-specular_axis), of a module that names Channels,
// CBits and TagBits:
//   `SPECULAR_AXIS_PX_PORTS   m_axis_px_tdata (Channels * CBits rounded up to whole bytes), _tlast,
//                             _tuser (the tag), _tvalid, _tready
//   `SPECULAR_AXIS_PX_MAP(P)  their connections to P``tdata .. P``tready

`ifndef SPECULAR_AXIL_PORTS_SVH
`define SPECULAR_AXIL_PORTS_SVH

`define SPECULAR_AXIL_PORTS \
  input  logic [AddrWidth-1:0] s_axil_awaddr, \
  input  logic [2:0]           s_axil_awprot, \
  input  logic                 s_axil_awvalid, \
  output logic                 s_axil_awready, \
  input  logic [31:0]          s_axil_wdata, \
  input  logic [3:0]           s_axil_wstrb, \
  input  logic                 s_axil_wvalid, \
  output logic                 s_axil_wready, \
  output logic [1:0]           s_axil_bresp, \
  output logic                 s_axil_bvalid, \
  input  logic                 s_axil_bready, \
  input  logic [AddrWidth-1:0] s_axil_araddr, \
  input  logic [2:0]           s_axil_arprot, \
  input  logic                 s_axil_arvalid, \
  output logic                 s_axil_arready, \
  output logic [31:0]          s_axil_rdata, \
  output logic [1:0]           s_axil_rresp, \
  output logic                 s_axil_rvalid, \
  input  logic                 s_axil_rready

`define SPECULAR_AXIL_MAP(P) \
  .s_axil_awaddr  (P``awaddr), \
  .s_axil_awprot  (P``awprot), \
  .s_axil_awvalid (P``awvalid), \
  .s_axil_awready (P``awready), \
  .s_axil_wdata   (P``wdata), \
  .s_axil_wstrb   (P``wstrb), \
  .s_axil_wvalid  (P``wvalid), \
  .s_axil_wready  (P``wready), \
  .s_axil_bresp   (P``bresp), \
  .s_axil_bvalid  (P``bvalid), \
  .s_axil_bready  (P``bready), \
  .s_axil_araddr  (P``araddr), \
  .s_axil_arprot  (P``arprot), \
  .s_axil_arvalid (P``arvalid), \
  .s_axil_arready (P``arready), \
  .s_axil_rdata   (P``rdata), \
  .s_axil_rresp   (P``rresp), \
  .s_axil_rvalid  (P``rvalid), \
  .s_axil_rready  (P``rready)

`define SPECULAR_AXIS_PX_PORTS \
  output logic [((Channels * CBits + 7) / 8) * 8-1:0] m_axis_px_tdata, \
  output logic                             m_axis_px_tlast, \
  output logic [TagBits-1:0]               m_axis_px_tuser, \
  output logic                             m_axis_px_tvalid, \
  input  logic                             m_axis_px_tready

`define SPECULAR_AXIS_PX_MAP(P) \
  .m_axis_px_tdata  (P``tdata), \
  .m_axis_px_tlast  (P``tlast), \
  .m_axis_px_tuser  (P``tuser), \
  .m_axis_px_tvalid (P``tvalid), \
  .m_axis_px_tready (P``tready)

`endif  // SPECULAR_AXIL_PORTS_SVH
