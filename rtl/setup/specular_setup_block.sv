// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_block: block normalization, N components shifted by one common power of
// two, rounded half up, so that the largest magnitude lies in [2^(Bits-1), 2^Bits]; the zero
// vector stays 0 (the golden model's host::fixed::block_normalize; docs/setup_hw.md#the-datapath,
// steps 3 and 4). One vector per clock.
//
//   stage 1  |x_i|
//   stage 2  t = the top set bit of (OR of the |x_i|) (the OR has the bit width of the largest)
//   stage 3  y_i = (x_i 2^Bits) >> t: x_i >> (s - 1) for s = t + 1 - Bits > 0, x_i << (1 - s)
//            otherwise, exact either way; one right shifter, no adder
//   stage 4  (y_i + 1) >> 1: the rounding of s > 0; exact for s <= 0 (y_i even)
// Stages: specular_setup_pkg::BlockStages. en_i freezes every stage. No reset. With
// SetupII > 1 (en_i the folded setup's advance) stage 3's N shifts share one shifter over the
// slot's clocks (specular_setup_rshift_n).
//
// TopLo .. TopHi: where the caller's data puts t. A vector of bounded length (G, and x with c:
// docs/setup_hw.md#the-rtl derives their windows) needs a shifter of clog2(TopHi - TopLo
// + 1) steps, not clog2(InW): the part of the shift below TopLo is a constant one. A nonzero
// input whose t lies outside the window gives a wrong result; in_window (simulation only) says
// whether the value in stage 2 is zero or inside, for the caller's assertion on its valid spans.

`include "specular_assert.svh"

module specular_setup_block #(
  parameter int N    = 3,
  parameter int InW  = 64,
  parameter int Bits = 28,
  parameter int SetupII = 1,  // > 1: one shifter for the N components (specular_setup_rshift_n)
  parameter int TopLo   = 0,
  parameter int TopHi   = InW - 1
) (
  input  logic                    clk_i,
  input  logic                    en_i,
  input  logic [N*InW-1:0]        x_i,   // component i at [i*InW +: InW], signed
  output logic [N*(Bits+2)-1:0]   x_o    // component i at [i*(Bits+2) +: Bits+2], signed
);

  localparam int OutW   = Bits + 2;
  localparam int YW     = Bits + 3;
  localparam int Stages = 4;

  if (Stages != specular_setup_pkg::BlockStages) begin : gen_stage_check
    `SPEC_PARAM_ERROR("specular_setup_block: BlockStages disagrees with the stages built here")
  end
  if (InW < 2 || InW > 120 || Bits < 2) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_block: InW must be in 2..120, Bits >= 2")
  end
  if (TopLo < 0 || TopLo > TopHi || TopHi >= InW) begin : gen_window_check
    `SPEC_PARAM_ERROR("specular_setup_block: the window needs 0 <= TopLo <= TopHi < InW")
  end

  logic [N*InW-1:0] x1_q, x2_q, mag_q;
  logic [InW-1:0]   all_d;
  always_comb begin
    all_d = '0;
    for (int i = 0; i < N; i++) begin
      all_d = all_d | mag_q[i*InW +: InW];
    end
  end
  // The top set bit within the window: a tree, not a priority loop (specular_setup_prio).
  // For all_d = 0 every x_i is 0 and any shift gives 0: the index needs no zero case.
  localparam int WW = TopHi - TopLo + 1;
  localparam int PL = (WW > 1) ? $clog2(WW) : 1;
  logic          unused_any;
  logic [PL-1:0] top_d, top_q;
  if (WW > 1) begin : gen_top
    // Folded, mag_q holds for the slot: the window's OR is registered on every clock (valid
    // from the slot's second), so the tree starts at flip-flops, not after the OR of the
    // components (docs/setup_hw.md#the-folded-setup).
    logic [WW-1:0] win;
    if (SetupII > 1) begin : gen_win_reg
      always_ff @(posedge clk_i) win <= all_d[TopHi:TopLo];
    end else begin : gen_win_wire
      assign win = all_d[TopHi:TopLo];
    end
    specular_setup_prio #(.W(WW), .FromTop(1'b0)) u_top (.a_i (win), .any_o (unused_any), .value_o (top_d));
  end else begin : gen_top_fixed
    assign top_d      = '0;
    assign unused_any = all_d[TopLo];
  end
`ifndef SYNTHESIS
  /* verilator lint_off UNUSEDSIGNAL */  // read by name, by a caller that bounds the window
  logic in_window;
  /* verilator lint_on UNUSEDSIGNAL */
  assign in_window = all_d == '0 || ((all_d >> (TopHi + 1)) == '0 && all_d[TopHi:TopLo] != '0);
`endif

  // (x_i 2^Bits) >> TopLo, exact or a floor, then the rest of the shift.
  localparam int XW = InW + Bits - TopLo;
  logic [N*XW-1:0]  x2;
  logic [N*YW-1:0]  y_d;
  for (genvar i = 0; i < N; i++) begin : gen_x2
    logic signed [InW+Bits-1:0] full;
    assign full = {x2_q[i*InW +: InW], Bits'(0)};
    assign x2[i*XW +: XW] = XW'(full >>> TopLo);
  end
  // Folded, a shifter over the full range (more than four steps: G', whose length is not
  // bounded) takes two clocks (docs/setup_hw.md#the-folded-setup).
  specular_setup_rshift_n #(.N(N), .InW(XW), .OutW(YW), .SW(PL), .Signed(1'b1),
                            .SetupII(SetupII), .Split(SetupII > 1 && PL > 4)) u_shift (
    .clk_i (clk_i), .en_i (en_i), .a_i (x2), .s_i (top_q), .y_o (y_d));

  for (genvar i = 0; i < N; i++) begin : gen_comp
    logic signed [YW-1:0] y_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        // stage 1
        mag_q[i*InW +: InW] <= x_i[i*InW + InW - 1] ? InW'(-$signed(x_i[i*InW +: InW])) : x_i[i*InW +: InW];
        // stage 3 (the true value fits YW bits, so the truncation is exact)
        y_q <= y_d[i*YW +: YW];
        // stage 4
        x_o[i*OutW +: OutW] <= OutW'((y_q + YW'(1)) >>> 1);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      x1_q <= x_i;
      x2_q <= x1_q;
      top_q <= top_d;
    end
  end

endmodule
