// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// fpga_ooc_unit: out-of-context place-and-route harness around specular_unit (registered
// IO, five pins: clk_i, rst_ni, sdi_i, load_i, xor_o). See fpga_ooc_io.sv for the pins
// and rtl/fpga/README.md for the flow (scripts/fpga.sh). Not part of the device.
//
// Input word (InBits bits, shifted in msb first, applied on load_i), from the msb down:
//   c_we, c[CBits], dpsi_we, dpsi[AngleBits], psi0_we, psi0[AngleBits], n_we, n[NBits],
//   len_we, len[LenBits], start
// The loaded word stays applied until the next load (strobes are levels here).
// Output parity: intensity_o, valid_o, busy_o.
//
// Parameters: the interface widths are passed through to the core. Every other core
// parameter (ROM files, CosAddrBits, ...) keeps the core's own default unless
// scripts/fpga.sh sets it on the core module by name (chparam), so a changed default in
// rtl/ is never shadowed by a stale copy here.

module fpga_ooc_unit #(
  parameter int CBits     = 16,
  parameter int AngleBits = 32,
  parameter int NBits     = 10,
  parameter int LenBits   = 11
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic sdi_i,
  input  logic load_i,
  output logic xor_o
);

  localparam int InBits  = 5 + CBits + 2 * AngleBits + NBits + LenBits + 1;
  localparam int OutBits = CBits + 2;

  logic                 core_rst_n;
  logic [InBits-1:0]    core_in;
  logic                 c_we, dpsi_we, psi0_we, n_we, len_we, start;
  logic [CBits-1:0]     c, intensity;
  logic [AngleBits-1:0] dpsi, psi0;
  logic [NBits-1:0]     n;
  logic [LenBits-1:0]   len;
  logic                 valid, busy;

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
    .core_out_i  ({intensity, valid, busy})
  );

  assign {c_we, c, dpsi_we, dpsi, psi0_we, psi0, n_we, n, len_we, len, start} = core_in;

  specular_unit #(
    .CBits     (CBits),
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

endmodule
