// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_cordic_fold: CORDIC vectoring, angle only, folded in time for the folded
// setup (docs/setup_hw.md#the-folded-cordic): a chain of Segs segments, segment s holding
// iterations s Rounds .. (s + 1) Rounds - 1 of one vector, two clocks an iteration. On every
// start_i each segment takes the vector of the segment before it (segment 0: x_i, y_i), so a
// vector passes one segment per start. The golden model is
// host::fixed::cordic_angle(x, y, Frac, Iters, W) in model/host/setup_fixed.hpp, bit for bit: for
// (x, y) in Q(Frac) with |(x, y)| K < 2^(W-1-Frac) (K ~ 1.6468, the CORDIC gain) the angle is
// atan2(y, x) in (-pi, pi] up to the residual atan(2^-(Iters-1)), Q(Frac).
//
// Schedule: start_i loads segment 0 with (x_i, y_i) turned into the right half plane (x < 0:
// (x, y) negated, z = +pi when y >= 0, else -pi; z = 0 otherwise) and segment s > 0 with
// segment s - 1's registers. Round r of every segment takes two clocks: the shifted operands
// of iteration s Rounds + r, its angle constant and the direction are selected into
// registers, then the three sums are registered. With start_i high in clock c, done_o is
// high from clock c + Latency (two clocks a round, and one) until the next start_i, which
// must wait for it. The vector given at start j leaves at angle_o while done_o is high after
// start j + Segs - 1. Iterations from Iters on (the last segment's when Rounds does not divide
// Iters) leave the vector as it is.
//
// rst_ni (asynchronous, active low) clears the control only: the vectors in the chain are
// garbage until Segs starts have passed; the datapath registers have no reset.
//
// Why segments of two-clock iterations: a segment's shift takes only its Rounds amounts, a
// multiplexer tree of clog2(Rounds) levels over fixed shifts (not a barrel shifter), and the
// clock that holds the tree holds no carry chain; the clock that holds the sums holds no
// multiplexer of data. The angle constants are a ROM in LUTs, fixed::atan_word: the package's
// Q50 atan_q(i) rounded half up to Frac bits at elaboration (Yosys 0.23 cannot evaluate a
// real $atan). Each register is one sum, a + (b ^ {W{sub}}) + sub
// (docs/setup_hw.md#the-cordics-adders).

`include "specular_assert.svh"

module specular_setup_cordic_fold #(
  parameter int W      = 34,  // register bits: x, y, z, angle_o
  parameter int Frac   = 29,  // fraction bits of x, y and the angle
  parameter int Iters  = 28,  // CORDIC iterations
  parameter int Rounds = 7    // iterations a segment, 1..Iters
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                start_i,
  input  logic signed [W-1:0] x_i,
  input  logic signed [W-1:0] y_i,
  output logic signed [W-1:0] angle_o,
  output logic                done_o
);

  localparam bit ParamsOk = Iters >= 1 && Iters <= specular_setup_pkg::AtanIters &&
                            Frac >= 1 && Frac <= specular_setup_pkg::AtanFrac &&
                            W >= Frac + 3 && Rounds >= 1 && Rounds <= Iters;
  /* verilator lint_off UNUSEDPARAM */
  // Segments and the clock of done_o after start_i's: the header's figures, public for the
  // block test, which measures them.
  localparam int Segs    /*verilator public*/ = ParamsOk ? (Iters + Rounds - 1) / Rounds : 1;
  localparam int Latency /*verilator public*/ = 2 * Rounds + 1;
  /* verilator lint_on UNUSEDPARAM */
  localparam int CntW    = (Rounds > 1) ? $clog2(Rounds) : 1;
  localparam int Slots   = 1 << CntW;  // the multiplexers' words: Rounds, padded to 2^CntW
  localparam int PiFrac  = ParamsOk ? specular_setup_pkg::AtanFrac - Frac : 0;
  localparam logic signed [W-1:0] Pi =
      W'(specular_setup_pkg::rshift_round(128'(specular_setup_pkg::PiQ50), PiFrac));

  if (W < Frac + 3) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_fold: W must be >= Frac + 3 (pi in Q(Frac) with its sign)")
  end
  if (Frac < 1 || Frac > specular_setup_pkg::AtanFrac) begin : gen_frac_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_fold: Frac must be in 1..specular_setup_pkg::AtanFrac (50)")
  end
  if (Iters < 1 || Iters > specular_setup_pkg::AtanIters) begin : gen_iters_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_fold: Iters must be in 1..specular_setup_pkg::AtanIters (48)")
  end
  if (Rounds < 1 || Rounds > Iters) begin : gen_rounds_check
    `SPEC_PARAM_ERROR("specular_setup_cordic_fold: Rounds must be in 1..Iters")
  end

  // a + b when sub = 0, a - b when sub = 1, modulo 2^W: one adder.
  function automatic logic [W-1:0] add_sub(input logic [W-1:0] a, input logic [W-1:0] b,
                                           input logic sub);
    add_sub = a + (b ^ {W{sub}}) + {{(W-1){1'b0}}, sub};
  endfunction

  function automatic logic [W-1:0] atan_word(input int i);
    atan_word = W'(specular_setup_pkg::rshift_round(128'(specular_setup_pkg::atan_q50(i)), PiFrac));
  endfunction

  // ---------------------------------------------------------------------------------
  // Control, one for every segment: run_q (rounds left), ph_q (the sums' clock), cnt_q
  // (round), done_q
  // ---------------------------------------------------------------------------------
  logic            run_q, run_d, ph_q, ph_d, done_q, done_d;
  logic [CntW-1:0] cnt_q, cnt_d;
  logic            select, step;
  assign select = run_q && !ph_q;
  assign step   = run_q && ph_q;

  always_comb begin
    run_d  = run_q;
    ph_d   = ph_q;
    cnt_d  = cnt_q;
    done_d = done_q;
    if (start_i) begin
      run_d  = 1'b1;
      ph_d   = 1'b0;
      cnt_d  = '0;
      done_d = 1'b0;
    end else if (select) begin
      ph_d = 1'b1;
    end else if (step) begin
      ph_d = 1'b0;
      if (cnt_q == CntW'(Rounds - 1)) begin
        run_d  = 1'b0;
        done_d = 1'b1;
      end else begin
        cnt_d = cnt_q + CntW'(1);
      end
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      run_q  <= 1'b0;
      ph_q   <= 1'b0;
      cnt_q  <= '0;
      done_q <= 1'b0;
    end else begin
      run_q  <= run_d;
      ph_q   <= ph_d;
      cnt_q  <= cnt_d;
      done_q <= done_d;
    end
  end

  // ---------------------------------------------------------------------------------
  // Datapath: segment s's x, y, z at bits s W +: W of xs_q, ys_q, zs_q (no reset)
  // ---------------------------------------------------------------------------------
  logic [Segs*W-1:0] xs_q, ys_q, zs_q;

  // The half turn into segment 0 (0 - v as 0 + ~v + 1).
  logic         neg_in;
  logic [W-1:0] x_ld, y_ld, z_ld;
  assign neg_in = x_i[W-1];
  assign x_ld   = add_sub('0, x_i, neg_in);
  assign y_ld   = add_sub('0, y_i, neg_in);
  assign z_ld   = !neg_in ? '0 : (!y_i[W-1] ? Pi : -Pi);

  for (genvar s = 0; s < Segs; s++) begin : gen_seg
    logic signed [W-1:0] x, y, z;
    assign x = xs_q[s*W +: W];
    assign y = ys_q[s*W +: W];
    assign z = zs_q[s*W +: W];

    // The round's words {atan, x >>> i, y >>> i}: a binary tree of 2:1 multiplexers, node n
    // (bits (n - 1) 3W +: 3W) at depth floor(log2 n) selecting by cnt_q's bit
    // CntW - 1 - depth; leaf Slots + r is iteration s Rounds + r (the leaves past Rounds - 1
    // repeat the last one's), or the words 0 from Iters on, which leave the vector as it is.
    logic [(2*Slots-1)*3*W-1:0] tree /*verilator split_var*/;
    for (genvar r = 0; r < Slots; r++) begin : gen_leaf
      localparam int I = s * Rounds + ((r < Rounds) ? r : Rounds - 1);
      if (I < Iters) begin : gen_iter
        localparam logic [W-1:0] Atan = atan_word(I);
        assign tree[(Slots+r-1)*3*W +: 3*W] = {Atan, W'(x >>> I), W'(y >>> I)};
      end else begin : gen_idle
        assign tree[(Slots+r-1)*3*W +: 3*W] = '0;
      end
    end
    for (genvar n = 1; n < Slots; n++) begin : gen_node
      localparam int Sel = CntW - $clog2(n + 1);  // CntW - 1 - floor(log2 n)
      assign tree[(n-1)*3*W +: 3*W] = cnt_q[Sel] ? tree[2*n*3*W +: 3*W] : tree[(2*n-1)*3*W +: 3*W];
    end

    // The first clock of a round registers the shifted operands, the angle constant and the
    // direction. The constants fall with i, so the segment's first is its largest and sets the
    // register's width (AtW bits, the rest zero).
    localparam int AtW = (s * Rounds < Iters && atan_word(s * Rounds) > 1) ? $clog2(atan_word(s * Rounds) + 1) : 1;
    logic [W-1:0]   dx_q, dy_q, atan;
    logic [AtW-1:0] atan_q;
    logic           up_q;
    always_ff @(posedge clk_i) begin
      if (select) begin
        {dy_q, dx_q} <= tree[0 +: 2*W];
        atan_q       <= tree[2*W +: AtW];
        up_q         <= y[W-1];
      end
    end
    assign atan = W'(atan_q);
    logic unused_atan_top;
    assign unused_atan_top = ^tree[2*W+AtW +: W-AtW];

    // up: y < 0, the vector turns up: x - dx, y + dy, z - atan (else x + dx, y - dy, z + atan).
    // z's sum is add_sub written as one (W+1)-bit sum whose bit 0 makes the carry in, so that
    // Yosys' alumacc keeps it one carry chain.
    logic [W:0] z_sum;
    assign z_sum = {z, 1'b1} + {atan ^ {W{up_q}}, up_q};

    logic [W-1:0] x_in, y_in, z_in;
    if (s == 0) begin : gen_first
      assign x_in = x_ld;
      assign y_in = y_ld;
      assign z_in = z_ld;
    end else begin : gen_next
      assign x_in = xs_q[(s-1)*W +: W];
      assign y_in = ys_q[(s-1)*W +: W];
      assign z_in = zs_q[(s-1)*W +: W];
    end

    always_ff @(posedge clk_i) begin
      if (start_i) begin
        xs_q[s*W +: W] <= x_in;
        ys_q[s*W +: W] <= y_in;
        zs_q[s*W +: W] <= z_in;
      end else if (step) begin
        xs_q[s*W +: W] <= add_sub(x, dx_q, up_q);
        ys_q[s*W +: W] <= add_sub(y, dy_q, !up_q);
        zs_q[s*W +: W] <= z_sum[W:1];
      end
    end

    logic unused_z_sum;
    assign unused_z_sum = z_sum[0];
  end

  assign angle_o = zs_q[(Segs-1)*W +: W];
  assign done_o  = done_q;

  // The last segment's x and y are read by no one.
  logic unused_last;
  assign unused_last = ^{xs_q[(Segs-1)*W +: W], ys_q[(Segs-1)*W +: W]};

  // ---------------------------------------------------------------------------------
  // Assertions
  // ---------------------------------------------------------------------------------
  `SPEC_ASSERT(StartWhenIdle_A, !start_i || !run_q, clk_i, rst_ni)
  `SPEC_ASSERT(CntInRange_A, cnt_q <= CntW'(Rounds - 1), clk_i, rst_ni)
  `SPEC_ASSERT(DoneIdle_A, !(done_q && run_q), clk_i, rst_ni)

endmodule
