// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_fmul: N exact signed products p_j = a_j * b_j in one slot of SetupII clocks
// on a few tile multipliers, for the folded lean setup (SetupII > 1,
// docs/setup_hw.md#the-lean-datapath): its stages advance once per slot (en_i, the last
// clock of the slot), every operand holds still for the slot, and a product takes one stage.
//
// Each product is cut into TA x TB tiles of T = 18 bits of the magnitudes; a multiplier takes
// one 18x18 unsigned tile product per clock (registered tiles and product: an ECP5
// MULT18X18D), and an accumulator adds them shifted. A product is one chunk, or two (Q = 2,
// summed before p_o) when its tiles exceed a slot's steps; a multiplier owns whole chunks, P
// of them per slot, so the unit has M = ceil(N Q / P) multipliers
// (specular_setup_lean_pkg::fmul_mults): the tile count falls as SetupII grows. The clock of
// a slot (count c, restarted by en_i, held at SetupII - 1 while the stage waits):
//   c = 0               |a_j|, |b_j| and the signs registered
//   c = 1 + s           tile step s into the multiplier's input registers
//   c = 2 + s           its tile product registered
//   c = 3 + s           accumulated, subtracted for a negative product (inverted tile and a
//                       carry in, one carry chain), so the sum is the signed product
//   advance edge        p_o registered
// s < P * H <= SetupII - specular_setup_lean_pkg::FmulOverhead. Exact, so bit-exact
// with specular_setup_smul. No reset: the counter realigns at the first advance.

`include "specular_assert.svh"

module specular_setup_fmul #(
  parameter int N        = 1,
  parameter int ABits    = 18,
  parameter int BBits    = 18,
  parameter int TileBits = 18,  // 0 (LUT multiplier) or the DSP tile width; T = 18 for 0
  parameter int SetupII  = 8
) (
  input  logic                          clk_i,
  input  logic                          en_i,   // the stage advance: the slot's last clock
  input  logic [N*ABits-1:0]            a_i,    // N signed operands
  input  logic [N*BBits-1:0]            b_i,
  output logic [N*(ABits+BBits)-1:0]    p_o,    // N signed products (registered on en_i)
  // The same before the register, final from clock SetupII - 2 of the slot on: a caller that
  // rounds or adds a product in its own stage (log2, exp2) reads it there.
  output logic [N*(ABits+BBits)-1:0]    pc_o
);

  localparam int T     = specular_setup_lean_pkg::fmul_tile(TileBits);
  localparam int PBits = ABits + BBits;
  localparam int TA    = (ABits + T - 1) / T;
  localparam int TB    = (BBits + T - 1) / T;
  localparam int TP    = TA * TB;
  localparam int Q     = specular_setup_lean_pkg::fmul_split(ABits, BBits, TileBits, SetupII);
  localparam int H     = specular_setup_lean_pkg::fmul_chunk(ABits, BBits, TileBits, SetupII);
  localparam int P     = specular_setup_lean_pkg::fmul_per_mult(ABits, BBits, TileBits, SetupII);
  localparam int M     = specular_setup_lean_pkg::fmul_mults(N, ABits, BBits, TileBits, SetupII);
  localparam int CW    = $clog2(SetupII);

  if (N < 1 || ABits < 2 || BBits < 2 || SetupII < 2) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: N >= 1, ABits and BBits >= 2 and SetupII >= 2")
  end
  if (P < 1) begin : gen_slot_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: half a product's tiles must fit the slot (TA TB <= 2 (SetupII - FmulOverhead))")
  end

  // The slot's clock count.
  logic [CW-1:0] cnt_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      cnt_q <= '0;
    end else if (cnt_q < CW'(SetupII - 1)) begin
      cnt_q <= cnt_q + CW'(1);
    end
  end

  // c = 0: the magnitudes (|-2^(n-1)| = 2^(n-1) still fits n unsigned bits), padded to tiles.
  logic [N*TA*T-1:0] ma_q;
  logic [N*TB*T-1:0] mb_q;
  logic [N-1:0]      neg_q;
  for (genvar j = 0; j < N; j++) begin : gen_mag
    logic [ABits-1:0] a, am;
    logic [BBits-1:0] b, bm;
    assign a  = a_i[j*ABits +: ABits];
    assign b  = b_i[j*BBits +: BBits];
    assign am = a[ABits-1] ? -a : a;
    assign bm = b[BBits-1] ? -b : b;
    always_ff @(posedge clk_i) begin
      if (cnt_q == '0) begin
        ma_q[j*TA*T +: TA*T] <= (TA * T)'(am);
        mb_q[j*TB*T +: TB*T] <= (TB * T)'(bm);
        neg_q[j]             <= a[ABits-1] ^ b[BBits-1];
      end
    end
  end

  // Chunk k is part k % Q of product k / Q: tiles (k % Q) H .. (k % Q) H + H - 1 (a tile
  // index from TP on is a zero tile). Tile t is (t / TB, t % TB), weight 2^(T (t / TB + t % TB)).
  localparam int DW = $clog2(TA + TB - 1 + 1);  // the tile's diagonal t / TB + t % TB
  logic [N*Q*PBits-1:0] csum;
  for (genvar m = 0; m < M; m++) begin : gen_mult
    localparam int K0    = m * P;                              // its first chunk
    localparam int Pm    = (N * Q - K0 < P) ? N * Q - K0 : P;  // its chunks
    localparam int Steps = Pm * H;
    localparam int IAW   = $clog2(Pm * TA + 1);
    localparam int IBW   = $clog2(Pm * TB + 1);
    // Its tiles: chunk l's a tiles at l TA + i, b tiles at l TB + i (a narrow multiplexer
    // per multiplier, addressed by a small step decode).
    logic [Pm*TA*T-1:0] asrc;
    logic [Pm*TB*T-1:0] bsrc;
    for (genvar l = 0; l < Pm; l++) begin : gen_src
      assign asrc[l*TA*T +: TA*T] = ma_q[((K0 + l) / Q)*TA*T +: TA*T];
      assign bsrc[l*TB*T +: TB*T] = mb_q[((K0 + l) / Q)*TB*T +: TB*T];
    end
    // c = 1 + s: decode step s (narrow signals), load its tiles.
    logic [IAW-1:0] ia;
    logic [IBW-1:0] ib;
    logic [DW-1:0]  dg;
    logic           zero, first, neg;
    always_comb begin
      ia    = '0;
      ib    = '0;
      dg    = '0;
      zero  = 1'b1;
      first = 1'b0;
      neg   = 1'b0;
      for (int s = 0; s < Steps; s++) begin
        if (32'(cnt_q) == s + 1) begin
          ia    = IAW'((s / H) * TA + ((((K0 + s / H) % Q) * H + s % H) % TP) / TB);
          ib    = IBW'((s / H) * TB + ((((K0 + s / H) % Q) * H + s % H) % TP) % TB);
          dg    = DW'(((((K0 + s / H) % Q) * H + s % H) % TP) / TB + ((((K0 + s / H) % Q) * H + s % H) % TP) % TB);
          zero  = (((K0 + s / H) % Q) * H + s % H) >= TP;
          first = s % H == 0;
          neg   = neg_q[(K0 + s / H) / Q];
        end
      end
    end
    logic [T-1:0]   ta_d, tb_d, ta_q, tb_q;
    always_comb begin
      ta_d = '0;
      tb_d = '0;
      for (int i = 0; i < Pm * TA; i++) begin
        if (ia == IAW'(i)) ta_d = asrc[i*T +: T];
      end
      for (int i = 0; i < Pm * TB; i++) begin
        if (ib == IBW'(i)) tb_d = bsrc[i*T +: T];
      end
      if (zero) ta_d = '0;
    end
    logic [2*T-1:0] pp_q;
    logic [DW-1:0]  dg1_q, dg2_q;
    logic           first1_q, first2_q, neg1_q, neg2_q;
    always_ff @(posedge clk_i) begin
      ta_q     <= ta_d;
      tb_q     <= tb_d;
      dg1_q    <= dg;
      first1_q <= first;
      neg1_q   <= neg;
      // c = 2 + s
      pp_q     <= (2 * T)'(ta_q) * (2 * T)'(tb_q);
      dg2_q    <= dg1_q;
      first2_q <= first1_q;
      neg2_q   <= neg1_q;
    end
    // c = 3 + s: accumulate step s, subtracted for a negative product (the tile inverted, a
    // carry in: one carry chain); a chunk's first step restarts the sum, and the sum before it
    // moves to that chunk's register.
    logic [PBits-1:0] sh, acc_q;
    logic [PBits:0]   acc_d;
    always_comb begin
      sh = '0;
      for (int d = 0; d < TA + TB - 1; d++) begin
        if (dg2_q == DW'(d)) sh = PBits'({{PBits{1'b0}}, pp_q} << (d * T));
      end
      acc_d = {first2_q ? PBits'(0) : acc_q, 1'b1} + {sh ^ {PBits{neg2_q}}, neg2_q};
    end
    always_ff @(posedge clk_i) begin
      if (cnt_q >= CW'(3) && cnt_q < CW'(Steps + 3)) acc_q <= acc_d[PBits:1];
    end
    logic unused_cin;
    assign unused_cin = acc_d[0];  // the carry-in position
    for (genvar l = 0; l < Pm; l++) begin : gen_chunk
      if (l == Pm - 1) begin : gen_last
        assign csum[(K0 + l)*PBits +: PBits] = acc_q;
      end else begin : gen_res
        logic [PBits-1:0] res_q;
        always_ff @(posedge clk_i) begin
          if (32'(cnt_q) == (l + 1) * H + 3) res_q <= acc_q;
        end
        assign csum[(K0 + l)*PBits +: PBits] = res_q;
      end
    end
  end

  // The product: its chunks summed (one carry chain), already signed.
  logic [N*PBits-1:0] p_d;
  for (genvar j = 0; j < N; j++) begin : gen_prod
    if (Q == 1) begin : gen_one
      assign p_d[j*PBits +: PBits] = csum[j*PBits +: PBits];
    end else begin : gen_two
      assign p_d[j*PBits +: PBits] = csum[2*j*PBits +: PBits] + csum[(2*j+1)*PBits +: PBits];
    end
  end

  assign pc_o = p_d;
  always_ff @(posedge clk_i) begin
    if (en_i) p_o <= p_d;
  end

endmodule
