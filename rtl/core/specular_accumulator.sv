// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Angle accumulator of patent UA 71489: adder 6, 2:1 multiplexer 7 and register 8.
// On the first strobe of a span (mux select 36 low) register 8 loads psi0; on every further
// strobe it loads psi + dpsi (register 2). Write strobe of reg 8 is 37.
//
// Erratum (docs/device.md#errata-of-the-patent-and-how-each-is-resolved): the patent loads register 3 with -sqrt(n/k)*lambda, but multiplier 11
// scales the accumulator output afterwards, so registers 3 and 2 hold the unscaled angles
// psi0 = -lambda and dpsi = gamma / l, in radians.
//
// Width: AccBits = AngleBits + 12 so that 2047 additions of the most negative dpsi to
// the most negative psi0 cannot overflow (2^31 * 2049 < 2^43).
//
// Register 8 is split in two halves so that no clock holds a full-width carry chain (a
// 44-bit adder is the slowest path of an iCE40-UP5K otherwise): stage A (written by the
// strobe) holds the low LoBits of psi and the carry out of their addition; stage B (moved
// by step_i, when A's pixel goes on) adds the high half with that carry one clock later.
// psi_o = {high half of B, low half delayed into B}: psi one clock after the strobe that
// made it, exact for every pixel. The stream writes stage A at every pipeline advance
// (we_i = adv) rather than only on the strobe: where no strobe is due, stage A's pixel is
// invalid (its valid bit is the control unit's), and a clock enable shared with the rest of
// the pipeline keeps the strobe logic off the clock-enable network of an iCE40.

`include "specular_assert.svh"

module specular_accumulator #(
  parameter int AngleBits = 32,   // registers 2 and 3, signed, radians
  parameter int AccBits   = 44    // register 8, signed, same fraction bits
) (
  input  logic                        clk_i,
  input  logic                        rst_ni,
  input  logic                        we_i,      // write 37 of register 8 (strobe): stage A
  input  logic                        sel_i,     // mux 7 select 36: 0 = psi0, 1 = psi + dpsi
  input  logic                        step_i,    // stage A's pixel moves to stage B
  input  logic signed [AngleBits-1:0] psi0_i,    // register 3
  input  logic signed [AngleBits-1:0] dpsi_i,    // register 2
  output logic signed [AccBits-1:0]   psi_o      // register 8 (stage B)
);

  localparam int LoBits = AccBits / 2;
  localparam int HiBits = AccBits - LoBits;

  if (specular_pkg::AccStages != 2) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_accumulator: register 8 is built as two halves (specular_pkg::AccStages)")
  end
  if (AccBits < AngleBits + 1) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_accumulator: AccBits must exceed AngleBits")
  end

  logic [AccBits-1:0] psi0_ext, dpsi_ext;

  // Sign extension to the accumulator width.
  assign psi0_ext = {{(AccBits-AngleBits){psi0_i[AngleBits-1]}}, psi0_i};
  assign dpsi_ext = {{(AccBits-AngleBits){dpsi_i[AngleBits-1]}}, dpsi_i};

  // Stage A: low half (adder 6, low part), mux 7; the high operands wait beside it.
  logic [LoBits-1:0] lo_q;
  logic              carry_q, load_q;
  logic [HiBits-1:0] hi0_q, dhi_q;
  logic [LoBits:0]   lo_sum;
  assign lo_sum = {1'b0, lo_q} + {1'b0, dpsi_ext[LoBits-1:0]};

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      lo_q    <= '0;
      carry_q <= 1'b0;
      load_q  <= 1'b0;
      hi0_q   <= '0;
      dhi_q   <= '0;
    end else if (we_i) begin
      if (!sel_i) begin
        lo_q    <= psi0_ext[LoBits-1:0];
        carry_q <= 1'b0;
      end else begin
        {carry_q, lo_q} <= lo_sum;
      end
      load_q <= ~sel_i;
      hi0_q  <= psi0_ext[AccBits-1:LoBits];
      dhi_q  <= dpsi_ext[AccBits-1:LoBits];
    end
  end

  // Stage B: high half (adder 6, high part) with the carry, and the low half.
  logic [HiBits-1:0] hi_q;
  logic [LoBits-1:0] lo_b_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      hi_q   <= '0;
      lo_b_q <= '0;
    end else if (step_i) begin
      hi_q   <= load_q ? hi0_q : hi_q + dhi_q + HiBits'(carry_q);
      lo_b_q <= lo_q;
    end
  end

  assign psi_o = {hi_q, lo_b_q};

  // Assertions (rtl/prim/specular_assert.svh): the strobes are never X, the operand a write
  // takes is known (psi0 on the first strobe, dpsi on the others), so register 8 never
  // holds an X.
  `SPEC_ASSERT_KNOWN(StrobesKnown_A, {we_i, sel_i, step_i}, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(Psi0Known_A, psi0_i, we_i && !sel_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(DpsiKnown_A, dpsi_i, we_i && sel_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(PsiKnown_A, psi_o, clk_i, rst_ni)

endmodule
