// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Output register slice of the stream (part of output 27 and strobe 29): a two-entry
// buffer between the pipeline and the pixel handshake, so that px_ready_i reaches only
// this buffer's flip-flops and the pipeline advance is a register (adv_o). Without it
// px_ready_i would gate every stage register combinationally: on an iCE40-UP5K that path
// (ready -> enable logic -> global clock-enable buffer) is the slowest of the core.
//
//   adv_o     registered: 1 when the buffer will hold at most one pixel at the next edge,
//             so that a pixel pushed then always has room (two entries suffice)
//   adv_d_o   adv_o's value after the next edge (combinational), for a caller that gates the
//             advance and registers the result (the folded setup)
//   push      in_valid_i at an edge where adv_o is high (the pipeline's last stage moves)
//   pop       px_valid_o && px_ready_i (AXI4-Stream transfer)
// px_valid_o and px_data_o are registers: once valid, they hold until the transfer, and
// px_valid_o never waits for px_ready_i. px_data_o reads 0 while px_valid_o is low. With
// px_ready_i always high the buffer holds at most one pixel and adv_o stays high: one
// pixel per clock, one clock of latency.

`include "specular_assert.svh"

module specular_out_buf #(
  parameter int Width = 33
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  output logic             adv_o,       // pipeline advance (a register)
  output logic             adv_d_o,     // adv_o at the next edge
  input  logic             in_valid_i,  // the pipeline's last stage holds a pixel
  input  logic [Width-1:0] in_data_i,
  output logic             px_valid_o,
  input  logic             px_ready_i,
  output logic [Width-1:0] px_data_o
);

  logic [1:0]       count_q, count_d;
  logic [Width-1:0] head_q, head_d, tail_q, tail_d;
  logic             adv_q, adv_d, push, pop;

  assign push = adv_q & in_valid_i;
  assign pop  = (count_q != 2'd0) & px_ready_i;

  // Each register loads under an enable of its own, and head's next value has one control
  // input besides the data (push): written as one case over {push, pop, count}, every bit's
  // next value is a function of seven signals, which the ECP5 mapping builds as a LUT7 per bit
  // (about 10 LUT4 a bit at Width 120, against 1 this way).
  logic head_en, tail_en;
  always_comb begin
    // push alone into an empty buffer, push and pop, or pop alone. Push and pop together find
    // one pixel: a pop needs an entry, and a push needs adv_q, the registered room (count <= 1,
    // AdvIsRoom_A), so the buffer is never full then.
    head_en = (push && (pop || count_q == 2'd0)) || (pop && !push);
    head_d  = push ? in_data_i : ((count_q == 2'd2) ? tail_q : '0);
    // push alone behind a held pixel
    tail_en = push && !pop && count_q != 2'd0;
    tail_d  = in_data_i;
    unique case ({push, pop})
      2'b10:   count_d = count_q + 2'd1;
      2'b01:   count_d = count_q - 2'd1;
      default: count_d = count_q;
    endcase
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      count_q <= 2'd0;
      head_q  <= '0;
      tail_q  <= '0;
      adv_q   <= 1'b1;
    end else begin
      count_q <= count_d;
      if (head_en) head_q <= head_d;
      if (tail_en) tail_q <= tail_d;
      adv_q   <= adv_d;
    end
  end

  assign adv_d      = count_d <= 2'd1;
  assign adv_o      = adv_q;
  assign adv_d_o    = adv_d;
  assign px_valid_o = count_q != 2'd0;
  assign px_data_o  = head_q;

  // Assertions (rtl/prim/specular_assert.svh). At most two entries, and the advance is the
  // registered "room" (so a push never meets a full buffer: the push-and-pop arm above
  // relies on it); while stalled the pixel stays valid and unchanged; an empty buffer reads
  // 0; a valid pixel is known.
  `SPEC_ASSERT(CountMax_A, count_q <= 2'd2, clk_i, rst_ni)
  `SPEC_ASSERT(AdvIsRoom_A, adv_q == (count_q <= 2'd1), clk_i, rst_ni)
  `SPEC_ASSERT_IF(HoldWhileStalled_A, px_valid_o && !px_ready_i, count_d != 2'd0 && !head_en, clk_i, rst_ni)
  `SPEC_ASSERT_IF(EmptyReadsZero_A, !px_valid_o, px_data_o == '0, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(InputsKnown_A, {in_valid_i, px_ready_i}, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(PushKnown_A, in_data_i, push, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(DataKnown_A, px_data_o, px_valid_o, clk_i, rst_ni)

endmodule
