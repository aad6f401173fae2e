// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// fpga_ooc_io: the registered IO of the out-of-context place-and-route harness fpga_ooc
// (rtl/fpga/README.md). Not part of the device.
//
// A core under test has far more input and output bits than an iCE40 package has pins
// (a core has a hundred or more inputs, a small package a few dozen IO), and the timing out
// of context must not include a pin: every core input and output passes through a
// flip-flop here, all clocked by the core clock.
//
//   clk_i     the core clock
//   rst_ni    asynchronous reset pin, active low; the core's reset core_rst_no is asserted
//             with it and released two clocks after it (async assert, sync release)
//   sdi_i     serial data: shifted each clock into an InBits-bit shift register (msb first)
//   load_i    load strobe: the shift register is copied into the core input register,
//             which drives core_in_o until the next load
//   core_out_i  every core output; registered, then reduced by a two-stage registered
//             XOR tree to
//   xor_o     one pin: the parity of all core outputs (every output bit reaches it, so
//             synthesis cannot remove any part of the core)
// sdi_i and load_i are registered before use, so no pin sits on a path to or from the core.

module fpga_ooc_io #(
  parameter int InBits  = 8,
  parameter int OutBits = 8
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               sdi_i,
  input  logic               load_i,
  output logic               xor_o,
  output logic               core_rst_no,
  output logic [InBits-1:0]  core_in_o,
  input  logic [OutBits-1:0] core_out_i
);

  // Groups of four outputs are XORed in the first stage.
  localparam int Groups = (OutBits + 3) / 4;

  if (InBits < 2) begin : gen_in_check
    $error("fpga_ooc_io: InBits must be >= 2");
  end

  // Reset: asserted asynchronously, released synchronously (two flip-flops).
  logic [1:0] rst_sync_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rst_sync_q <= '0;
    else         rst_sync_q <= {rst_sync_q[0], 1'b1};
  end
  assign core_rst_no = rst_sync_q[1];

  // Pins into flip-flops, then the serial-in shift register and the parallel load.
  logic              sdi_q, load_q;
  logic [InBits-1:0] shift_q, in_q;
  always_ff @(posedge clk_i) begin
    sdi_q   <= sdi_i;
    load_q  <= load_i;
    shift_q <= {shift_q[InBits-2:0], sdi_q};
    if (load_q) in_q <= shift_q;
  end
  assign core_in_o = in_q;

  // Every core output into a flip-flop, then a registered XOR tree to one pin.
  logic [OutBits-1:0]  out_q;
  logic [4*Groups-1:0] out_padded;
  logic [Groups-1:0]   group_q;
  logic                xor_q;
  assign out_padded = (4 * Groups)'(out_q);  // zero-extended
  always_ff @(posedge clk_i) begin
    out_q <= core_out_i;
    for (int g = 0; g < Groups; g++) begin
      group_q[g] <= ^out_padded[4*g +: 4];
    end
    xor_q <= ^group_q;
  end
  assign xor_o = xor_q;

endmodule
