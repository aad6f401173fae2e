// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Delay line of Depth registers with a common enable (pipeline stall): carries per-pixel
// side values (C, tag, bank, flags) beside the datapath so they reach each block in the
// same clock as their pixel. Depth = 0 is a wire.
// Reset = 1: asynchronous reset to 0 (values that must read 0 before the first pixel).
// Reset = 0: no reset, for datapath values whose validity travels in reset valid bits
// elsewhere (block RAM and multiplier outputs have no reset either); rst_ni is unused.
//
// Ram = 1 lets a long, wide line of Reset = 0 sit in block RAM instead of Width * Depth
// flip-flops: a ring of 2^clog2(Depth) words, written at a free-running pointer on every
// enabled edge, read (registered, same enable) at the word written Depth - 2 enabled edges
// earlier, then registered once more in the fabric (same enable), so q_o is the register
// chain's clock for clock, stalls included. The second register takes the RAM's slow
// clock-to-output off the path to the line's user (docs/setup_hw.md#the-folded-setup). The pointer
// needs no reset (every value of it is a valid ring position), so rst_ni stays unused.
// The style applies from RamMinDepth and RamMinBits on: a 36-bit-wide ECP5 DP16KD port
// replaces about 36 * Depth flip-flops, so short lines stay in registers, and narrow ones
// do not spend a block RAM on a few hundred bits. Opt-in (Ram defaults to 0): every other
// user keeps its register netlist, and iCE40 parts keep their few RAMs for the ROMs.

`include "specular_assert.svh"

module specular_delay #(
  parameter int Width = 1,
  parameter int Depth = 1,
  parameter bit Reset = 1'b1,
  parameter bit Ram   = 1'b0,   // may use the RAM style (Reset = 0 lines only)
  parameter int RamMinDepth = 8,
  parameter int RamMinBits  = 512
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             en_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);

  if (Width < 1 || Depth < 0) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_delay: Width must be >= 1 and Depth >= 0")
  end

  localparam bit InRam = Ram && !Reset && Depth >= RamMinDepth && Depth >= 3 && Width * Depth >= RamMinBits;

  // Three generate blocks of their own, not an else-if chain: the register style keeps its
  // hierarchical name gen_regs.line_q, which the formal harnesses read (scripts/formal.sh).
  if (Depth == 0) begin : gen_wire
    logic unused_clk;
    assign unused_clk = clk_i ^ rst_ni ^ en_i;
    assign q_o = d_i;
  end
  if (Depth > 0 && InRam) begin : gen_ram
    localparam int AW    = $clog2(Depth);
    localparam int Words = 1 << AW;
    // The word read is never the word written in the same clock (0 < Depth - 2 < Words):
    // no_rw_check spares Yosys the logic that resolves such a collision.
    (* no_rw_check *) logic [Width-1:0] mem [Words];
    logic [AW-1:0]    wp_q, rp_q;
    logic [Width-1:0] ram_q, q_q;
    logic             unused_rst;
    assign unused_rst = rst_ni;
    // rp_q follows wp_q after the first enabled edge: the word written Depth - 2 edges before
    // the next write, so that ram_q and q_q make Depth with it.
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        wp_q <= wp_q + AW'(1);
        rp_q <= wp_q + AW'(Words + 3 - Depth);
      end
    end
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        mem[wp_q] <= d_i;
        ram_q     <= mem[rp_q];
      end
    end
    // Kept out of the block RAM: Yosys 0.23 maps no DP16KD output register (REGMODE stays NOREG).
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        q_q <= ram_q;
      end
    end
    assign q_o = q_q;
  end
  if (Depth > 0 && !InRam) begin : gen_regs
    // Stage j (1 .. Depth) is line_q[j*Width-1 -: Width]; d_i enters at the bottom.
    logic [Depth*Width-1:0] line_d, line_q;
    if (Depth == 1) begin : gen_one
      assign line_d = d_i;
    end else begin : gen_shift
      assign line_d = {line_q[(Depth-1)*Width-1:0], d_i};
    end
    if (Reset) begin : gen_reset
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) begin
          line_q <= '0;
        end else if (en_i) begin
          line_q <= line_d;
        end
      end
    end else begin : gen_no_reset
      logic unused_rst;
      assign unused_rst = rst_ni;
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          line_q <= line_d;
        end
      end
    end
    assign q_o = line_q[Depth*Width-1 -: Width];
  end

  // Assertions (rtl/prim/specular_assert.svh): the enable of a line with reset is never X (an
  // X enable would smear the whole line).
  if (Reset && Depth > 0) begin : gen_known_check
    `SPEC_ASSERT_KNOWN(EnKnown_A, en_i, clk_i, rst_ni)
  end

endmodule
