// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Control unit, block 14 of patent UA 71489, for the streaming pipeline. The patent builds
// it from four D flip-flops, a pulse generator and AND / inverter / NAND gates clocked by
// the generator phases, and runs one line at a time. Here everything is synchronous to
// clk_i, a pipeline advance (adv) replaces the generator, and spans follow each other with
// no gap. The patent's four flip-flops map to:
//   start latch   the span handshake: a span is taken (accept) when span_valid_i and
//                 span_ready_o are high; specular_unit keeps a real start latch in front
//   run           vld_q[0]: register 8 holds a pixel (the strobe 37 wrote one)
//   mux select 36 sel_o: 0 on the strobe that loads psi0 of an accepted span, else 1
//   count enable  count_o: the count pulse 34 of counter 5, one per pixel leaving reg 8
// The data-valid strobe 29 is vld_q delayed along the PipeDepth stages (register 8 ->
// multiplier 11 -> ROM 12 -> multiplier 13 / output register: specular_stream sets
// PipeDepth from the blocks' latencies; the default 5 serves the block test); last_q marks
// the pixel that took the borrow 35 of counter 5 (the last of its span).
//
// Handshake (AXI4-Stream rules on the span side; the pixel side is specular_out_buf):
//   adv_i         every stage register moves at this edge (a register of the output
//                 buffer: high whenever the buffer has room for the last stage's pixel)
//   span_ready_o  = adv_i && (register 8 empty || it holds its span's last pixel)
// span_ready_o therefore depends on registers only, never on span_valid_i or px_ready_i.
// With adv_i high a new span's first pixel enters register 8 on the edge at which the
// previous span's last pixel leaves it: one pixel per clock, l = 0 spans included.

`include "specular_assert.svh"

module specular_control #(
  parameter int PipeDepth = 5
) (
  input  logic clk_i,
  input  logic rst_ni,
  input  logic span_valid_i,   // a span is offered
  output logic span_ready_o,   // ... and would be taken at this edge
  input  logic adv_i,          // every pipeline stage advances at this edge
  input  logic cnt_zero_i,     // counter 5 holds 0: the pixel in register 8 is its span's last
  output logic accept_o,       // span handshake: registers 1, 2, 4, counter 5 load
  output logic strobe_o,       // write 37 of register 8
  output logic sel_o,          // mux select 36: 0 = psi0 of the accepted span, 1 = psi + dpsi
  output logic count_o,        // count pulse 34 of counter 5
  output logic [PipeDepth-1:0] stage_valid_o,  // stage j holds a pixel (0: register 8)
  output logic out_valid_o,    // data valid strobe 29: the last stage holds a pixel
  output logic out_last_o,     // ... the last of its span
  output logic busy_o          // some pixel is in flight
);

  if (PipeDepth < 2) begin : gen_depth_check
    `SPEC_PARAM_ERROR("specular_control: PipeDepth must be >= 2")
  end

  logic [PipeDepth-1:0] vld_d, vld_q;
  logic [PipeDepth-1:1] last_d, last_q;
  logic free0, more0;

  assign more0        = vld_q[0] & ~cnt_zero_i;      // register 8 has more pixels to make
  assign free0        = ~vld_q[0] | cnt_zero_i;      // register 8 is free after this edge
  assign span_ready_o = adv_i & free0;
  assign accept_o     = span_valid_i & span_ready_o;
  assign strobe_o     = adv_i & (accept_o | more0);
  assign sel_o        = ~accept_o;
  assign count_o      = adv_i & vld_q[0];

  assign vld_d  = {vld_q[PipeDepth-2:0], accept_o | more0};
  if (PipeDepth > 2) begin : gen_last_shift
    assign last_d = {last_q[PipeDepth-2:1], vld_q[0] & cnt_zero_i};
  end else begin : gen_last_single
    assign last_d = vld_q[0] & cnt_zero_i;
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      vld_q  <= '0;
      last_q <= '0;
    end else if (adv_i) begin
      vld_q  <= vld_d;
      last_q <= last_d;
    end
  end

  assign stage_valid_o = vld_q;
  assign out_valid_o   = vld_q[PipeDepth-1];
  assign out_last_o    = last_q[PipeDepth-1];
  assign busy_o        = |vld_q;

  // Assertions (rtl/prim/specular_assert.svh). State legality: a last flag only on a valid
  // stage, and no gap inside a span (a valid stage that is not its span's last pixel has
  // a valid stage right behind it). Inputs: never X; a span offered and not taken is
  // still offered at the next clock (AXI4-Stream: valid waits for ready).
  `SPEC_ASSERT(LastIsValid_A, (last_q & ~vld_q[PipeDepth-1:1]) == '0, clk_i, rst_ni)
  `SPEC_ASSERT(NoGapInSpan_A, (vld_q[PipeDepth-1:1] & ~last_q & ~vld_q[PipeDepth-2:0]) == '0, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(InputsKnown_A, {span_valid_i, adv_i, cnt_zero_i}, clk_i, rst_ni)
`ifndef SYNTHESIS
  logic offered_q;   // a span was offered and not taken at the last edge
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      offered_q <= 1'b0;
    end else begin
      offered_q <= span_valid_i & ~span_ready_o;
    end
  end
  `SPEC_ASSERT_IF(SpanValidHeld_A, offered_q, span_valid_i, clk_i, rst_ni)
`endif

endmodule
