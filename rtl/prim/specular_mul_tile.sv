// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// One DSP tile: p = a * b, both operands registered and then the product, en_i the clock
// enable of all three registers. Signed takes both operands and the product as two's
// complement. No reset: a tile carries data only.
//
// The registers are the DSP's own (docs/pipeline.md#multiplier-styles): with
// SPECULAR_ECP5_MULT18X18D defined (scripts/fpga.py defines it for its ECP5 runs) the tile is
// a MULT18X18D with its input A, input B and output registers on CLK0 / CE0, so no route
// between a fabric register and the multiplier is on a path; otherwise the same behaviour in
// fabric registers and a `*` (simulation, the UP5K's SB_MAC16 and Yosys' generic mapping).
// Yosys 0.23 maps a product to a combinational MULT18X18D only (share/yosys/ecp5/dsp_map.v),
// hence the instance.

`include "specular_assert.svh"

module specular_mul_tile #(
  parameter int Bits   = 18,    // operand width
  parameter bit Signed = 1'b1,  // two's complement operands and product
  // The bits of a_i / b_i that can differ from their extension (the rest are 0, or copies of
  // the sign when signed): a tile with a 1-bit operand is an AND, left to the fabric.
  parameter int ALive  = Bits,
  parameter int BLive  = Bits
) (
  input  logic                clk_i,
  input  logic                en_i,
  input  logic [Bits-1:0]     a_i,
  input  logic [Bits-1:0]     b_i,
  output logic [2*Bits-1:0]   p_o
);

  if (Bits < 2 || ALive < 1 || ALive > Bits || BLive < 1 || BLive > Bits) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_mul_tile: Bits must be >= 2, ALive and BLive from 1 to Bits")
  end

  // Prim: the ECP5 primitive; the instance is under the define too (no other tool knows it).
`ifdef SPECULAR_ECP5_MULT18X18D
  localparam bit Prim = ALive >= 2 && BLive >= 2;
`else
  localparam bit Prim = 1'b0;
`endif

`ifdef SPECULAR_ECP5_MULT18X18D
  if (Prim && Bits > 18) begin : gen_ecp5_width_check
    `SPEC_PARAM_ERROR("specular_mul_tile: a MULT18X18D takes at most 18 bits an operand")
  end
  if (Prim) begin : gen_mult18x18d
    // Operands extended to the primitive's 18 bits as the sign mode reads them.
    logic [17:0] a18, b18;
    logic [35:0] p36;
    assign a18 = Signed ? 18'($signed(a_i)) : 18'(a_i);
    assign b18 = Signed ? 18'($signed(b_i)) : 18'(b_i);
    MULT18X18D #(
      .REG_INPUTA_CLK  ("CLK0"),
      .REG_INPUTA_CE   ("CE0"),
      .REG_INPUTA_RST  ("RST0"),
      .REG_INPUTB_CLK  ("CLK0"),
      .REG_INPUTB_CE   ("CE0"),
      .REG_INPUTB_RST  ("RST0"),
      .REG_OUTPUT_CLK  ("CLK0"),
      .REG_OUTPUT_CE   ("CE0"),
      .REG_OUTPUT_RST  ("RST0"),
      .GSR             ("DISABLED"),
      .RESETMODE       ("SYNC")
    ) u_mult (
      .A0 (a18[0]),  .A1 (a18[1]),  .A2 (a18[2]),  .A3 (a18[3]),  .A4 (a18[4]),  .A5 (a18[5]),
      .A6 (a18[6]),  .A7 (a18[7]),  .A8 (a18[8]),  .A9 (a18[9]),  .A10(a18[10]), .A11(a18[11]),
      .A12(a18[12]), .A13(a18[13]), .A14(a18[14]), .A15(a18[15]), .A16(a18[16]), .A17(a18[17]),
      .B0 (b18[0]),  .B1 (b18[1]),  .B2 (b18[2]),  .B3 (b18[3]),  .B4 (b18[4]),  .B5 (b18[5]),
      .B6 (b18[6]),  .B7 (b18[7]),  .B8 (b18[8]),  .B9 (b18[9]),  .B10(b18[10]), .B11(b18[11]),
      .B12(b18[12]), .B13(b18[13]), .B14(b18[14]), .B15(b18[15]), .B16(b18[16]), .B17(b18[17]),
      .C0 (1'b0), .C1 (1'b0), .C2 (1'b0), .C3 (1'b0), .C4 (1'b0), .C5 (1'b0), .C6 (1'b0),
      .C7 (1'b0), .C8 (1'b0), .C9 (1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0),
      .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
      .SIGNEDA (Signed), .SIGNEDB (Signed), .SOURCEA (1'b0), .SOURCEB (1'b0),
      .CLK0 (clk_i), .CLK1 (1'b0), .CLK2 (1'b0), .CLK3 (1'b0),
      .CE0 (en_i), .CE1 (1'b0), .CE2 (1'b0), .CE3 (1'b0),
      .RST0 (1'b0), .RST1 (1'b0), .RST2 (1'b0), .RST3 (1'b0),
      .P0 (p36[0]),  .P1 (p36[1]),  .P2 (p36[2]),  .P3 (p36[3]),  .P4 (p36[4]),  .P5 (p36[5]),
      .P6 (p36[6]),  .P7 (p36[7]),  .P8 (p36[8]),  .P9 (p36[9]),  .P10(p36[10]), .P11(p36[11]),
      .P12(p36[12]), .P13(p36[13]), .P14(p36[14]), .P15(p36[15]), .P16(p36[16]), .P17(p36[17]),
      .P18(p36[18]), .P19(p36[19]), .P20(p36[20]), .P21(p36[21]), .P22(p36[22]), .P23(p36[23]),
      .P24(p36[24]), .P25(p36[25]), .P26(p36[26]), .P27(p36[27]), .P28(p36[28]), .P29(p36[29]),
      .P30(p36[30]), .P31(p36[31]), .P32(p36[32]), .P33(p36[33]), .P34(p36[34]), .P35(p36[35])
    );
    assign p_o = p36[2*Bits-1:0];
  end
`endif
  if (!Prim) begin : gen_fabric
    // Only the live bits are registered and multiplied (a synthesis of this module alone, as
    // a hierarchical one is, cannot see that the rest are extensions).
    logic [ALive-1:0]  a_q;
    logic [BLive-1:0]  b_q;
    logic [2*Bits-1:0] p_d, p_q;
    if (Signed) begin : gen_signed
      assign p_d = (2 * Bits)'($signed(a_q) * $signed(b_q));
    end else begin : gen_unsigned
      assign p_d = (2 * Bits)'(a_q) * (2 * Bits)'(b_q);
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        a_q <= a_i[ALive-1:0];
        b_q <= b_i[BLive-1:0];
        p_q <= p_d;
      end
    end
    assign p_o = p_q;
  end

  // Assertions (rtl/prim/specular_assert.svh): the bits above ALive / BLive are the extension
  // of the live ones, as the caller states (on known operands: a bubble's may be X).
`ifndef SYNTHESIS
  logic [Bits-1:0] a_ext, b_ext;
  assign a_ext = Signed ? Bits'($signed(a_i[ALive-1:0])) : Bits'(a_i[ALive-1:0]);
  assign b_ext = Signed ? Bits'($signed(b_i[BLive-1:0])) : Bits'(b_i[BLive-1:0]);
  `SPEC_ASSERT_IF(ALive_A, en_i && `SPEC_KNOWN(a_i), a_i == a_ext, clk_i, 1'b1)
  `SPEC_ASSERT_IF(BLive_A, en_i && `SPEC_KNOWN(b_i), b_i == b_ext, clk_i, 1'b1)
`endif

endmodule
