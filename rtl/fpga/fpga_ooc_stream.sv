// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// fpga_ooc_stream: out-of-context place-and-route harness around specular_stream
// (registered IO, five pins: clk_i, rst_ni, sdi_i, load_i, xor_o). See fpga_ooc_io.sv for
// the pins and rtl/fpga/README.md for the flow (scripts/fpga.sh). Not part of the device.
//
// Input word (InBits bits, shifted in msb first, applied on load_i), from the msb down:
//   span_valid, c[CBits], psi0[AngleBits], dpsi[AngleBits], n[NBits], len[LenBits],
//   tag[TagBits], px_ready
// The loaded word stays applied until the next load.
// Output parity: span_ready_o, px_valid_o, px_intensity_o, px_last_o, px_tag_o.
//
// Parameters: the interface widths are passed through to the core; every other core
// parameter keeps the core's default unless scripts/fpga.sh sets it on the core module by
// name (chparam).

module fpga_ooc_stream #(
  parameter int CBits     = 16,
  parameter int AngleBits = 32,
  parameter int NBits     = 10,
  parameter int LenBits   = 11,
  parameter int TagBits   = 16
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  input  logic load_i,
  output logic xor_o
);

  localparam int InBits  = 2 + CBits + 2 * AngleBits + NBits + LenBits + TagBits;
  localparam int OutBits = 3 + CBits + TagBits;

  logic                 core_rst_n;
  logic [InBits-1:0]    core_in;
  logic                 span_valid, span_ready, px_valid, px_ready, px_last;
  logic [CBits-1:0]     c, px_intensity;
  logic [AngleBits-1:0] psi0, dpsi;
  logic [NBits-1:0]     n;
  logic [LenBits-1:0]   len;
  logic [TagBits-1:0]   tag, px_tag;

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
    .core_out_i  ({span_ready, px_valid, px_intensity, px_last, px_tag})
  );

  assign {span_valid, c, psi0, dpsi, n, len, tag, px_ready} = core_in;

  specular_stream #(
    .CBits     (CBits),
    .AngleBits (AngleBits),
    .NBits     (NBits),
    .LenBits   (LenBits),
    .TagBits   (TagBits)
  ) u_core (
    .clk_i          (clk_i),
    .rst_ni         (core_rst_n),
    .span_valid_i   (span_valid),
    .span_ready_o   (span_ready),
    .span_c_i       (c),
    .span_psi0_i    (psi0),
    .span_dpsi_i    (dpsi),
    .span_n_i       (n),
    .span_len_i     (len),
    .span_tag_i     (tag),
    .px_valid_o     (px_valid),
    .px_ready_i     (px_ready),
    .px_intensity_o (px_intensity),
    .px_last_o      (px_last),
    .px_tag_o       (px_tag)
  );

endmodule
