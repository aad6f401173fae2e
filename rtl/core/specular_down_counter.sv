// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Down counter, block 5 of patent UA 71489: holds the pixel count l (input 23, write 24),
// decrements on every count pulse (34) and raises its borrow (35) on the pulse that
// takes it past zero. A line of l + 1 pixels therefore gets l + 1 count pulses and the
// borrow comes with the last one; the count then stays 0 until the next write. As in the
// patent, l is written before every line (the stream loads it with each accepted span;
// specular_unit keeps l in its own register, so l persists from line to line there).

`include "specular_assert.svh"

module specular_down_counter #(
  parameter int LenBits = 11
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               len_we_i,   // write 24, qualified by "idle"
  input  logic [LenBits-1:0] len_i,      // input 23
  input  logic               count_i,    // count pulse 34
  output logic               borrow_o,   // borrow 35: this count pulse passes zero
  output logic               zero_o,     // the count is 0 (a register: no compare on the path)
  output logic [LenBits-1:0] count_o     // current count (for observation)
);

  if (LenBits < 1) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_down_counter: LenBits must be >= 1")
  end

  logic [LenBits-1:0] cnt_d, cnt_q;
  logic               zero_d, zero_q;

  // zero_q == (cnt_q == 0) always; kept as its own register so that the control unit's
  // handshake (span_ready_o, the strobes) starts from a flip-flop, not an LenBits compare.
  assign borrow_o = count_i && zero_q;

  always_comb begin
    cnt_d  = cnt_q;
    zero_d = zero_q;
    if (len_we_i) begin
      cnt_d  = len_i;
      zero_d = (len_i == '0);
    end else if (count_i && !zero_q) begin   // the borrow pulse leaves the count at 0
      cnt_d  = cnt_q - 1'b1;
      zero_d = (cnt_q == LenBits'(1));
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      cnt_q  <= '0;
      zero_q <= 1'b1;
    end else begin
      cnt_q  <= cnt_d;
      zero_q <= zero_d;
    end
  end

  assign count_o = cnt_q;
  assign zero_o  = zero_q;

  // Assertions (rtl/prim/specular_assert.svh): the zero flag is the count's zero test, the
  // count never passes below zero (a decrement starts above zero, the borrow comes only at
  // zero); the strobes are never X.
  `SPEC_ASSERT(ZeroFlag_A, zero_q == (cnt_q == '0), clk_i, rst_ni)
  `SPEC_ASSERT_IF(BorrowAtZero_A, borrow_o, cnt_q == '0, clk_i, rst_ni)
  `SPEC_ASSERT_IF(NoWrap_A, count_i && !len_we_i && !borrow_o, cnt_q != '0, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(StrobesKnown_A, {len_we_i, count_i}, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(LenKnown_A, len_i, len_we_i, clk_i, rst_ni)

endmodule
