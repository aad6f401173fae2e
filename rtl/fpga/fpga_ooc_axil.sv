// SPDX-License-Identifier: Apache-2.0
//
// fpga_ooc_axil: out-of-context place-and-route harness around specular_axil (registered
// IO, five pins: clk_i, rst_ni, sdi_i, load_i, xor_o). See fpga_ooc_io.sv for the pins
// and rtl/fpga/README.md for the flow (scripts/fpga.sh). Not part of the device.
//
// Input word (InBits bits, shifted in msb first, applied on load_i), from the msb down:
//   awvalid, awaddr[AddrWidth], awprot[3], wvalid, wdata[32], wstrb[4], bready,
//   arvalid, araddr[AddrWidth], arprot[3], rready, m_axis_px_tready
// The loaded word stays applied until the next load (valids and readies are levels here).
// Output parity: awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid,
// m_axis_px_tdata, m_axis_px_tvalid, m_axis_px_tlast, m_axis_px_tuser, irq_o.
//
// Parameters: the interface widths (and AddrWidth) are passed through to the core; every
// other core parameter keeps the core's default unless scripts/fpga.sh sets it on the core
// module by name (chparam). AngleBits, NBits and LenBits are not port widths of
// specular_axil (its registers are 32 bits) but are passed on like in the other harnesses.

module fpga_ooc_axil #(
  parameter int CBits     = 16,
  parameter int AngleBits = 32,
  parameter int NBits     = 10,
  parameter int LenBits   = 11,
  parameter int TagBits   = 16,
  parameter int AddrWidth = 8
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  input  logic load_i,
  output logic xor_o
);

  localparam int PxBits  = ((CBits + 7) / 8) * 8;
  localparam int InBits  = 2 * AddrWidth + 48;
  localparam int OutBits = 41 + PxBits + 3 + TagBits;

  logic                 core_rst_n;
  logic [InBits-1:0]    core_in;
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
    .core_out_i  ({awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid,
                   px_tdata, px_tvalid, px_tlast, px_tuser, irq})
  );

  assign {awvalid, awaddr, awprot, wvalid, wdata, wstrb, bready,
          arvalid, araddr, arprot, rready, px_tready} = core_in;

  specular_axil #(
    .CBits     (CBits),
    .AngleBits (AngleBits),
    .NBits     (NBits),
    .LenBits   (LenBits),
    .TagBits   (TagBits),
    .AddrWidth (AddrWidth)
  ) u_core (
    .clk_i            (clk_i),
    .rst_ni           (core_rst_n),
    .s_axil_awaddr    (awaddr),
    .s_axil_awprot    (awprot),
    .s_axil_awvalid   (awvalid),
    .s_axil_awready   (awready),
    .s_axil_wdata     (wdata),
    .s_axil_wstrb     (wstrb),
    .s_axil_wvalid    (wvalid),
    .s_axil_wready    (wready),
    .s_axil_bresp     (bresp),
    .s_axil_bvalid    (bvalid),
    .s_axil_bready    (bready),
    .s_axil_araddr    (araddr),
    .s_axil_arprot    (arprot),
    .s_axil_arvalid   (arvalid),
    .s_axil_arready   (arready),
    .s_axil_rdata     (rdata),
    .s_axil_rresp     (rresp),
    .s_axil_rvalid    (rvalid),
    .s_axil_rready    (rready),
    .m_axis_px_tdata  (px_tdata),
    .m_axis_px_tvalid (px_tvalid),
    .m_axis_px_tready (px_tready),
    .m_axis_px_tlast  (px_tlast),
    .m_axis_px_tuser  (px_tuser),
    .irq_o            (irq)
  );

endmodule
