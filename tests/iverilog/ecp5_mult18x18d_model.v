// SPDX-License-Identifier: Apache-2.0
//
// A behavioural model of the ECP5 MULT18X18D, for tests only (Yosys 0.23 ships the primitive
// as a black box, share/yosys/ecp5/cells_bb.v, and no simulation model). Written from Lattice's
// description of the sysDSP slice (the ECP5 family data sheet, DS1044, and the ECP5 and
// ECP5-5G sysDSP usage guide, TN1267): P = A x B, 18 x 18 bits into 36, A and B each read as
// two's complement when SIGNEDA / SIGNEDB is high; an input register per operand and an
// output register, each bypassed ("NONE") or clocked by one of CLK0..3 with a clock enable and
// a reset of its own choosing. It implements what specular_mul_tile asks for and stops on any
// other setting, so that a change of the instance cannot pass unmodelled: registers on CLK0
// with CE0 and RST0 (synchronous reset), no pipeline register, parallel inputs (SOURCEA/B low).
`timescale 1ns / 1ps
module MULT18X18D #(
  parameter REG_INPUTA_CLK   = "NONE",
  parameter REG_INPUTA_CE    = "CE0",
  parameter REG_INPUTA_RST   = "RST0",
  parameter REG_INPUTB_CLK   = "NONE",
  parameter REG_INPUTB_CE    = "CE0",
  parameter REG_INPUTB_RST   = "RST0",
  parameter REG_INPUTC_CLK   = "NONE",
  parameter REG_PIPELINE_CLK = "NONE",
  parameter REG_OUTPUT_CLK   = "NONE",
  parameter REG_OUTPUT_CE    = "CE0",
  parameter REG_OUTPUT_RST   = "RST0",
  parameter GSR              = "ENABLED",
  parameter RESETMODE        = "SYNC"
) (
  input A0, A1, A2, A3, A4, A5, A6, A7, A8, A9, A10, A11, A12, A13, A14, A15, A16, A17,
  input B0, B1, B2, B3, B4, B5, B6, B7, B8, B9, B10, B11, B12, B13, B14, B15, B16, B17,
  input C0, C1, C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15, C16, C17,
  input SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
  input CLK0, CLK1, CLK2, CLK3,
  input CE0, CE1, CE2, CE3,
  input RST0, RST1, RST2, RST3,
  output P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17,
  output P18, P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34,
  output P35
);
  wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1, A0};
  wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1, B0};

  initial begin
    if ((REG_INPUTA_CLK != "NONE" && REG_INPUTA_CLK != "CLK0") ||
        (REG_INPUTB_CLK != "NONE" && REG_INPUTB_CLK != "CLK0") ||
        (REG_OUTPUT_CLK != "NONE" && REG_OUTPUT_CLK != "CLK0") ||
        REG_INPUTA_CE != "CE0" || REG_INPUTB_CE != "CE0" || REG_OUTPUT_CE != "CE0" ||
        REG_INPUTA_RST != "RST0" || REG_INPUTB_RST != "RST0" || REG_OUTPUT_RST != "RST0" ||
        REG_PIPELINE_CLK != "NONE" || RESETMODE != "SYNC")
      $fatal(1, "MULT18X18D model (%m): a register setting it does not implement");
  end
  always @(posedge CLK0) begin
    if (SOURCEA !== 1'b0 || SOURCEB !== 1'b0)
      $fatal(1, "MULT18X18D model (%m): SOURCEA/SOURCEB (shift inputs) not implemented");
  end

  reg  [17:0] a_q, b_q;
  reg  [35:0] p_q;
  wire [17:0] a_r = (REG_INPUTA_CLK == "CLK0") ? a_q : a;
  wire [17:0] b_r = (REG_INPUTB_CLK == "CLK0") ? b_q : b;
  // Each operand extended to 36 bits as its sign flag reads it; the product modulo 2^36.
  wire [35:0] a_x = {{18{SIGNEDA & a_r[17]}}, a_r};
  wire [35:0] b_x = {{18{SIGNEDB & b_r[17]}}, b_r};
  wire [35:0] p_d = a_x * b_x;
  wire [35:0] p   = (REG_OUTPUT_CLK == "CLK0") ? p_q : p_d;
  always @(posedge CLK0) begin
    if (RST0) begin
      a_q <= 18'd0;
      b_q <= 18'd0;
      p_q <= 36'd0;
    end else if (CE0) begin
      a_q <= a;
      b_q <= b;
      p_q <= p_d;
    end
  end
  assign {P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21, P20, P19,
          P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1, P0} = p;
endmodule
