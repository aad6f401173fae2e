// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_cordic_iter: CORDIC vectoring, angle only, folded in time: one set of
// PerClock iteration stages used over ceil(Iters / PerClock) clocks per vector, for the
// time-multiplexed setups (docs/setup_hw.md#the-lean-datapath, step 6). The golden model is
// host::lean::cordic_angle(x, y, Frac, Iters, W) in model/host/setup_lean.hpp, bit for bit:
// for (x, y) in Q(Frac) with |(x, y)| K < 2^(W-1-Frac) (K ~ 1.6468, the CORDIC gain) it
// gives angle_o = atan2(y, x) in (-pi, pi] up to the residual atan(2^-(Iters-1)), Q(Frac).
// Every value then stays inside the W-bit registers, which is what makes the W-bit sums
// equal to the model's 64-bit ones.
//
// Schedule (Rounds = ceil(Iters / PerClock), the round counter cnt_q):
//   accept clock      x_i, y_i are loaded with the half turn into the right half plane
//                     (x < 0: (x, y) negated, z = +pi when y >= 0, else -pi; z = 0 otherwise)
//   round r, clock    iterations i = r PerClock + k, k = 0..PerClock-1, chained through the
//   1 + r             PerClock stages in one clock (r = 0..Rounds-1); an iteration
//                     i >= Iters (the last round when PerClock does not divide Iters)
//                     leaves the vector as it is
//   then              out_valid_o until the transfer
// A vector accepted in clock c gives out_valid_o in clock c + Rounds + 1 (Latency), and the
// next vector is accepted in that same clock when out_ready_i is high: the initiation
// interval is II = Rounds + 1 clocks (5 at PerClock = 7, Iters = 28; 8 at PerClock = 4;
// 2 at PerClock = Iters, one clock of iterations). With OpReg (PerClock = 1) round r takes
// clocks 1 + 2r (its operands selected into registers) and 2 + 2r (the sums): Latency =
// II = 2 Rounds + 1.
//
// Handshake: AXI4-Stream rules on both sides. in_ready_o is high when the unit is empty or
// its result leaves in this clock (in_ready_o = !busy || (out_valid_o && out_ready_i), so it
// depends on out_ready_i, never on in_valid_i); out_valid_o and angle_o hold until the
// transfer. rst_ni (asynchronous, active low) clears the control only: a vector in flight is
// dropped; the datapath registers have no reset, every vector loads them first.
//
// Why folded: the pipelined specular_setup_cordic takes a vector per clock with 3 registers
// of W bits per iteration; a setup that accepts a span every few clocks needs only PerClock
// stages and three registers, at the price of II clocks per vector.
//
// Coding (docs/setup_hw.md#the-cordics-adders): each register of a stage is one sum,
// a + (b ^ {W{sub}}) + sub (add_sub), one carry chain, not two sums and a multiplexer (z's
// is the same sum written with W + 1 bits, see gen_stage). The shift of stage k takes only
// the Rounds amounts r PerClock + k, so it is a Rounds-way multiplexer (a tree of 2:1
// multiplexers on cnt_q's bits) over fixed shifts, not a barrel shifter; the angle constant
// of stage k is a Rounds-word ROM (LUTs) in the same tree, its words lean::atan_word: the
// package's Q50 atan_q(i) rounded half up to Frac bits at elaboration (Yosys 0.23 cannot
// evaluate a real $atan).

`include "specular_assert.svh"

module specular_setup_cordic_iter #(
  parameter int W        = 34,  // register bits: x, y, z, angle_o
  parameter int Frac     = 29,  // fraction bits of x, y and the angle
  parameter int Iters    = 28,  // CORDIC iterations
  parameter int PerClock = 4,   // iterations per clock, 1..Iters
  // 1 (with PerClock = 1): two clocks an iteration, the selected operands registered in the
  // first, the sums in the second, so no clock holds both the round's multiplexer and a carry
  // chain (docs/setup_hw.md#the-folded-cordic).
  parameter bit OpReg    = 1'b0
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                in_valid_i,
  output logic                in_ready_o,
  input  logic signed [W-1:0] x_i,
  input  logic signed [W-1:0] y_i,
  output logic                out_valid_o,
  input  logic                out_ready_i,
  output logic signed [W-1:0] angle_o
);

  localparam bit ParamsOk = PerClock >= 1 && PerClock <= Iters && Iters >= 1 &&
                            Iters <= specular_setup_pkg::CordicIters && Frac >= 1 &&
                            Frac <= specular_setup_pkg::CordicFrac && W >= Frac + 3;
  // Rounds of PerClock iterations, the initiation interval and the latency (clocks). II and
  // Latency are the figures of the header, public for the block test, which measures them.
  localparam int Rounds  = ParamsOk ? (Iters + PerClock - 1) / PerClock : 1;
  /* verilator lint_off UNUSEDPARAM */
  localparam int II      /*verilator public*/ = (OpReg ? 2 : 1) * Rounds + 1;
  localparam int Latency /*verilator public*/ = (OpReg ? 2 : 1) * Rounds + 1;
  /* verilator lint_on UNUSEDPARAM */
  localparam int CntW    = (Rounds > 1) ? $clog2(Rounds) : 1;
  localparam int Slots   = 1 << CntW;  // the multiplexers' words: Rounds, padded to 2^CntW
  localparam int PiFrac  = specular_setup_pkg::CordicFrac - Frac;
  localparam logic signed [W-1:0] Pi =
      W'(specular_setup_pkg::rshift_round(128'(specular_setup_pkg::Pi), PiFrac));

  // Pi needs Frac + 3 bits with its sign; the constants are the package's Q50 words for
  // i < CordicIters.
  if (W < Frac + 3) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_iter: W must be >= Frac + 3 (pi in Q(Frac) with its sign)")
  end
  if (Frac < 1 || Frac > specular_setup_pkg::CordicFrac) begin : gen_frac_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_iter: Frac must be in 1..specular_setup_pkg::CordicFrac (50)")
  end
  if (Iters < 1 || Iters > specular_setup_pkg::CordicIters) begin : gen_iters_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_iter: Iters must be in 1..specular_setup_pkg::CordicIters (48)")
  end
  if (PerClock < 1 || PerClock > Iters) begin : gen_per_clock_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_iter: PerClock must be in 1..Iters")
  end
  if (OpReg && PerClock != 1) begin : gen_op_reg_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_iter: OpReg needs PerClock = 1")
  end

  // a + b when sub = 0, a - b when sub = 1, modulo 2^W: one adder, b inverted and the carry in
  // set by sub (docs/setup_hw.md#the-cordics-adders).
  function automatic logic [W-1:0] add_sub(input logic [W-1:0] a, input logic [W-1:0] b,
                                           input logic sub);
    add_sub = a + (b ^ {W{sub}}) + {{(W-1){1'b0}}, sub};
  endfunction

  // lean::atan_word(i, Frac): round(atan(2^-i) 2^50) rounded half up to Frac bits.
  function automatic logic [W-1:0] atan_word(input int i);
    atan_word = W'(specular_setup_pkg::rshift_round(128'(specular_setup_pkg::atan_q(i)), PiFrac));
  endfunction

  // ---------------------------------------------------------------------------------
  // Control: busy_q (a vector in the unit), out_valid_q (its angle is final), cnt_q (round)
  // ---------------------------------------------------------------------------------
  logic            busy_q, busy_d, out_valid_q, out_valid_d;
  logic [CntW-1:0] cnt_q, cnt_d;
  logic            load, iterate, step;
  // OpReg: ph_q is the iteration's second clock (the sums); 1 always without OpReg.
  logic            ph_q, ph_d;

  assign in_ready_o = !busy_q || (out_valid_q && out_ready_i);
  assign load       = in_valid_i && in_ready_o;
  assign iterate    = busy_q && !out_valid_q;
  assign step       = iterate && ph_q;

  always_comb begin
    busy_d      = busy_q;
    out_valid_d = out_valid_q;
    cnt_d       = cnt_q;
    ph_d        = ph_q;
    if (load) begin
      busy_d      = 1'b1;
      out_valid_d = 1'b0;
      cnt_d       = '0;
      ph_d        = !OpReg;
    end else if (iterate && !ph_q) begin
      ph_d = 1'b1;
    end else if (iterate) begin
      ph_d = !OpReg;
      if (cnt_q == CntW'(Rounds - 1)) begin
        out_valid_d = 1'b1;
      end else begin
        cnt_d = cnt_q + CntW'(1);
      end
    end else if (out_valid_q && out_ready_i) begin
      busy_d      = 1'b0;
      out_valid_d = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      busy_q      <= 1'b0;
      out_valid_q <= 1'b0;
      cnt_q       <= '0;
      ph_q        <= !OpReg;
    end else begin
      busy_q      <= busy_d;
      out_valid_q <= out_valid_d;
      cnt_q       <= cnt_d;
      ph_q        <= ph_d;
    end
  end

  // ---------------------------------------------------------------------------------
  // Datapath: x_q, y_q, z_q (no reset)
  // ---------------------------------------------------------------------------------
  logic signed [W-1:0] x_q, y_q, z_q, x_d, y_d, z_d;

  // The half turn at load: (x, y) negated when x < 0 (0 - v as 0 + ~v + 1); z = +-pi.
  logic                neg_in;
  logic signed [W-1:0] x_ld, y_ld, z_ld;
  assign neg_in = x_i[W-1];
  assign x_ld   = add_sub('0, x_i, neg_in);
  assign y_ld   = add_sub('0, y_i, neg_in);
  assign z_ld   = !neg_in ? '0 : (!y_i[W-1] ? Pi : -Pi);

  // x_s, y_s, z_s word k (bits k W +: W): into stage k of this clock (k = 0: the registers).
  // Flat vectors (Yosys 0.23 has no packed arrays of arrays), split into a variable per
  // stage for Verilator, whose scheduler then sees no loop through the vector.
  logic [(PerClock+1)*W-1:0] x_s /*verilator split_var*/, y_s /*verilator split_var*/,
                             z_s /*verilator split_var*/;
  assign x_s[0 +: W] = x_q;
  assign y_s[0 +: W] = y_q;
  assign z_s[0 +: W] = z_q;

  for (genvar k = 0; k < PerClock; k++) begin : gen_stage
    logic [W-1:0] x, y, z;
    assign x = x_s[k*W +: W];
    assign y = y_s[k*W +: W];
    assign z = z_s[k*W +: W];

    // The Rounds-way multiplexer of the stage's operands {atan, dy, dx} by cnt_q: a binary tree
    // of 2:1 multiplexers, node n (1..2 Slots - 1, bits (n - 1) 3W +: 3W) of depth floor(log2 n)
    // selecting by cnt_q's bit CntW - 1 - depth between its children 2n and 2n + 1; leaf
    // Slots + r is round r's words: iteration i = r PerClock + k, its two fixed shifts and its
    // angle constant (the leaves past Rounds - 1 repeat the last round's). An iteration
    // i >= Iters (only in the last round) has the words 0: add_sub(a, 0, s) = a for either s,
    // the stage passes the vector on. (A part-select by cnt_q W would be a general shifter
    // for Yosys, and an AND-OR of the words maps worse.)
    logic [(2*Slots-1)*3*W-1:0] tree /*verilator split_var*/;
    for (genvar r = 0; r < Slots; r++) begin : gen_leaf
      localparam int I = ((r < Rounds) ? r : Rounds - 1) * PerClock + k;
      if (I < Iters) begin : gen_iter
        localparam logic [W-1:0] Atan = atan_word(I);
        assign tree[(Slots+r-1)*3*W +: 3*W] = {Atan, W'($signed(x) >>> I), W'($signed(y) >>> I)};
      end else begin : gen_idle
        assign tree[(Slots+r-1)*3*W +: 3*W] = '0;
      end
    end
    for (genvar n = 1; n < Slots; n++) begin : gen_node
      localparam int Sel = CntW - $clog2(n + 1);  // CntW - 1 - floor(log2 n)
      assign tree[(n-1)*3*W +: 3*W] = cnt_q[Sel] ? tree[2*n*3*W +: 3*W] : tree[(2*n-1)*3*W +: 3*W];
    end

    logic [W-1:0] dx, dy, atan;
    logic         up_sel;
    if (OpReg) begin : gen_op_reg
      // The first clock of the iteration registers the root and the direction (x, y, z
      // hold); the second adds them.
      logic [3*W-1:0] op_q;
      logic           up_q;
      always_ff @(posedge clk_i) begin
        if (iterate && !ph_q) begin
          op_q <= tree[0 +: 3*W];
          up_q <= y[W-1];
        end
      end
      assign {atan, dy, dx} = op_q;
      assign up_sel         = up_q;
    end else begin : gen_op_wire
      assign {atan, dy, dx} = tree[0 +: 3*W];  // the root
      assign up_sel         = y[W-1];
    end

    // up: y < 0, the vector turns up: x - dx, y + dy, z - atan (else x + dx, y - dy, z + atan).
    // z's sum is add_sub written as one (W+1)-bit sum whose bit 0 makes the carry in,
    // {z, 1} + {atan ^ {W{up}}, up}: the same W bits, but Yosys' alumacc does not merge the
    // stages' z sums (each used once) into one multi-operand $macc, which it would build
    // from LUTs instead of PerClock carry chains.
    logic       up;
    logic [W:0] z_sum;
    assign up       = up_sel;
    assign z_sum    = {z, 1'b1} + {atan ^ {W{up}}, up};
    assign x_s[(k+1)*W +: W] = add_sub(x, dx, up);
    assign y_s[(k+1)*W +: W] = add_sub(y, dy, !up);
    assign z_s[(k+1)*W +: W] = z_sum[W:1];

    logic unused_z_sum;
    assign unused_z_sum = z_sum[0];
  end

  always_comb begin
    x_d = x_q;
    y_d = y_q;
    z_d = z_q;
    if (load) begin
      x_d = x_ld;
      y_d = y_ld;
      z_d = z_ld;
    end else if (step) begin
      x_d = x_s[PerClock*W +: W];
      y_d = y_s[PerClock*W +: W];
      z_d = z_s[PerClock*W +: W];
    end
  end

  always_ff @(posedge clk_i) begin
    x_q <= x_d;
    y_q <= y_d;
    z_q <= z_d;
  end

  assign out_valid_o = out_valid_q;
  assign angle_o     = z_q;

  // ---------------------------------------------------------------------------------
  // Assertions
  // ---------------------------------------------------------------------------------
  `SPEC_ASSERT(CntInRange, cnt_q <= CntW'(Rounds - 1), clk_i, rst_ni)
  `SPEC_ASSERT(ValidOnlyBusy, !out_valid_q || busy_q, clk_i, rst_ni)
  `SPEC_ASSERT(PhaseOnlyOpReg, OpReg || ph_q, clk_i, rst_ni)

endmodule
