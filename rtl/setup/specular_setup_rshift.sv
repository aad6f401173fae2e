// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_rshift: y_o = the low OutW bits of a_i >> s_i (arithmetic for Signed = 1), as
// a logarithmic shifter whose largest step comes first. Only the low OutW bits are kept, so
// after each step fewer bits are still needed: the step by 2^k keeps OutW + 2^k - 1 of them.
// Yosys 0.23 maps ">>" with its smallest step first, each step as wide as the input: for a
// block normalizer's 80-bit input and 31-bit output, 990 LUT4 against 537 this way
// (docs/setup_hw.md#the-rtl). Combinational.

module specular_setup_rshift #(
  parameter int InW    = 8,
  parameter int OutW   = 8,
  parameter int SW     = 3,     // s_i's bits
  parameter bit Signed = 1'b0
) (
  input  logic [InW-1:0]  a_i,
  input  logic [SW-1:0]   s_i,
  output logic [OutW-1:0] y_o
);

  // Wide enough that no step loses a bit the output needs, and at least OutW.
  localparam int VW = (InW > OutW) ? InW : OutW;

  logic [VW-1:0] v;
  always_comb begin
    v = Signed ? VW'($signed(a_i)) : VW'(a_i);
    for (int k = SW - 1; k >= 0; k--) begin
      if (s_i[k]) begin
        v = Signed ? VW'($signed(v) >>> (1 << k)) : v >> (1 << k);
      end
    end
  end
  assign y_o = v[OutW-1:0];

endmodule
