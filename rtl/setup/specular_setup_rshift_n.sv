// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_rshift_n: N values shifted right by one common amount (specular_setup_rshift
// each), for a pipeline stage that registers y_o on its enable en_i. With SetupII = 1 these are
// N shifters and y_o is combinational. With SetupII > 1 (the folded setup, en_i the advance at
// a slot's last clock, a_i and s_i still for the slot) value c is selected into a register in
// clock c of the slot and one shifter takes it into a register of its own in clock c + 1, so
// y_o is ready before the advance: N - 1 shifters fewer for N multiplexer inputs
// (docs/setup_hw.md#the-folded-setup), and the selection and the shift are in clocks of
// their own. That needs SetupII > N + 1. A stalled slot only repeats the last value's shift.
// Split = 1 (folded only) takes the shift in two clocks, its larger steps into a register of
// OutW + 2^Lo - 1 bits (Lo = SW / 2, the smaller steps' amount bits) and the rest in the next
// clock: for a shifter of many steps, whose levels and routes did not fit one clock
// (docs/setup_hw.md#the-folded-setup). That needs SetupII > N + 2.

`include "specular_assert.svh"

module specular_setup_rshift_n #(
  parameter int N       = 3,
  parameter int InW     = 8,
  parameter int OutW    = 8,
  parameter int SW      = 3,
  parameter bit Signed  = 1'b0,
  parameter int SetupII = 1,
  parameter bit Split   = 1'b0
) (
  input  logic              clk_i,
  input  logic              en_i,
  input  logic [N*InW-1:0]  a_i,   // value i at [i*InW +: InW]
  input  logic [SW-1:0]     s_i,
  output logic [N*OutW-1:0] y_o
);

  if (N < 1 || SetupII < 1 || (SetupII > 1 && N > 1 && SetupII <= N + 1)) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup_rshift_n: N >= 1, and a folded SetupII must exceed N + 1")
  end
  if (Split && (SetupII == 1 || N == 1 || SW < 2 || SetupII <= N + 2)) begin : gen_split_check
    `SPEC_PARAM_ERROR("specular_setup_rshift_n: Split needs a folded shifter (SetupII > 1, N > 1) of SW >= 2 and SetupII > N + 2")
  end
  // The clocks from a value's selection to its result.
  localparam int Lat = Split ? 2 : 1;

  if (SetupII == 1 || N == 1) begin : gen_par
    logic unused_clk;
    assign unused_clk = clk_i ^ en_i;
    for (genvar i = 0; i < N; i++) begin : gen_shift
      specular_setup_rshift #(.InW(InW), .OutW(OutW), .SW(SW), .Signed(Signed)) u_shift (
        .a_i (a_i[i*InW +: InW]), .s_i (s_i), .y_o (y_o[i*OutW +: OutW]));
    end
  end else begin : gen_fold
    // The slot's clock, restarted by the advance and held at the last value. No reset: it
    // realigns at the first advance, before any value that matters.
    // c_q counts to N + Lat - 1: value c is selected at c_q = c, shifted and held at
    // c_q = c + Lat.
    localparam int CW = $clog2(N + Lat);
    logic [CW-1:0]   c_q;
    logic [InW-1:0]  a_c, a_c_q;
    logic [OutW-1:0] y_c;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        c_q <= '0;
      end else if (c_q != CW'(N + Lat - 1)) begin
        c_q <= c_q + CW'(1);
      end
    end
    // From c_q = N - 1 on the last value stays selected: a stalled slot repeats its shift.
    always_comb begin
      a_c = a_i[(N-1)*InW +: InW];
      for (int i = 0; i < N - 1; i++) begin
        if (c_q == CW'(i)) a_c = a_i[i*InW +: InW];
      end
    end
    always_ff @(posedge clk_i) begin
      a_c_q <= a_c;
    end
    if (Split) begin : gen_split
      // a >> s = (a >> (s_hi 2^Lo)) >> s_lo; the first keeps the bits the second can reach.
      localparam int Lo   = SW / 2;
      localparam int MidW = OutW + (1 << Lo) - 1;
      logic [MidW-1:0] mid, mid_q;
      specular_setup_rshift #(.InW(InW), .OutW(MidW), .SW(SW), .Signed(Signed)) u_shift_hi (
        .a_i (a_c_q), .s_i ({s_i[SW-1:Lo], Lo'(0)}), .y_o (mid));
      always_ff @(posedge clk_i) begin
        mid_q <= mid;
      end
      specular_setup_rshift #(.InW(MidW), .OutW(OutW), .SW(Lo), .Signed(Signed)) u_shift_lo (
        .a_i (mid_q), .s_i (s_i[Lo-1:0]), .y_o (y_c));
    end else begin : gen_one
      specular_setup_rshift #(.InW(InW), .OutW(OutW), .SW(SW), .Signed(Signed)) u_shift (
        .a_i (a_c_q), .s_i (s_i), .y_o (y_c));
    end
    for (genvar i = 0; i < N; i++) begin : gen_hold
      always_ff @(posedge clk_i) begin
        if (!en_i && c_q == CW'(i + Lat)) y_o[i*OutW +: OutW] <= y_c;
      end
    end
  end

endmodule
