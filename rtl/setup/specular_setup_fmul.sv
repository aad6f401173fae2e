// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_fmul: N exact signed products p_j = a_j * b_j in one slot of SetupII clocks
// on a few tile multipliers, for the folded setup (SetupII > 1,
// docs/setup_hw.md#the-folded-setup): its stages advance once per slot (en_i, the last
// clock of the slot) and a product takes Stages stages, 1 (p_o registered) or 0 (p_o final in
// the slot's last clock, for a caller that registers its own result). The operands must hold
// still for the whole slot (they are the stages' registers), so the unit reads them tile by
// tile and serves products of different stages alike.
//
// An operand is cut into unsigned low tiles of T - 1 bits and a signed top tile of at most
// T bits (T = 18), so every tile product is one signed 18x18 product (registered tiles and
// product: an ECP5 MULT18X18D) and no magnitude or sign is needed. The tiles go in the order
// of their weight's diagonal i + j, so the accumulator only ever moves by one tile's weight:
// where a diagonal ends, its low T - 1 bits are final and leave for a segment register, and
// the accumulator shifts right by T - 1 (a fixed shift, AccW bits instead of a product-wide
// adder behind a shifter of every diagonal). A product is one chunk, or two (Q = 2, summed before p_o) when its
// tiles exceed a slot's steps; a multiplier owns whole chunks, P of them per slot, so the
// unit has M = ceil(N Q / P) multipliers (specular_setup_pkg::fmul_mults): the tile
// count falls as SetupII grows. The clock of a slot (count c, restarted by en_i, held at
// SetupII - 1 while the stage waits):
//   c = s       tile step s into its multiplier's input registers
//   c = 1 + s   its tile product registered
//   c = 2 + s   accumulated (a new diagonal first moves the low bits out; a chunk's last
//               step moves the sum out and clears the sum)
//   advance     p_o registered (Stages = 1), or read by the caller (Stages = 0)
// s < P * H <= SetupII - specular_setup_pkg::FmulOverhead. Exact, so bit-exact with
// specular_setup_smul. No reset: the counter realigns at the first advance.

`include "specular_assert.svh"

module specular_setup_fmul #(
  parameter int N        = 1,
  parameter int ABits    = 18,
  parameter int BBits    = 18,
  parameter int TileBits = 18,  // 0 (LUT multiplier) or the DSP tile width; T = 18 for 0
  parameter int SetupII  = 8,
  // The product's stages: 1, p_o registered on en_i; 0, p_o is pc_o (one chunk a product, so
  // no adder: the caller registers what it derives from it on en_i,
  // specular_setup_pkg::fold_mul_stages).
  parameter int Stages   = 1
) (
  input  logic                          clk_i,
  input  logic                          en_i,   // the stage advance: the slot's last clock
  input  logic [N*ABits-1:0]            a_i,    // N signed operands, still for the slot
  input  logic [N*BBits-1:0]            b_i,
  output logic [N*(ABits+BBits)-1:0]    p_o,    // N signed products (Stages = 1: registered on en_i)
  // The same before the register, final from clock SetupII - 2 of the slot on: a caller that
  // rounds or adds a product in its own stage (log2, exp2) reads it there.
  output logic [N*(ABits+BBits)-1:0]    pc_o
);

  localparam int T     = specular_setup_pkg::fmul_tile(TileBits);
  localparam int PBits = ABits + BBits;
  localparam int TA    = specular_setup_pkg::fmul_tiles_of(ABits, TileBits);
  localparam int TB    = specular_setup_pkg::fmul_tiles_of(BBits, TileBits);
  localparam int TP    = TA * TB;
  localparam int Q     = specular_setup_pkg::fmul_split(ABits, BBits, TileBits, SetupII);
  localparam int H     = specular_setup_pkg::fmul_chunk(ABits, BBits, TileBits, SetupII);
  localparam int P     = specular_setup_pkg::fmul_per_mult(ABits, BBits, TileBits, SetupII);
  localparam int M     = specular_setup_pkg::fmul_mults(N, ABits, BBits, TileBits, SetupII);
  localparam int CW    = $clog2(SetupII);
  localparam int TokenMinSteps = 12;
  // The accumulator: a diagonal's at most min(TA, TB) tile products (each |p| <= 2^(2T - 2))
  // plus the carry of the diagonals below it (< 2^(T + 1)) fit 2T + 2 signed bits for up to
  // four tiles a diagonal; two more bits of margin.
  localparam int AccW  = 2 * T + 4;

  // Step s of a multiplier whose first chunk is k0: chunk k0 + s / H, its r-th tile in the
  // diagonal order (a zero tile from TP on).
  function automatic int step_r(input int s, input int k0);
    step_r = ((k0 + s / H) % Q) * H + s % H;
  endfunction
  // The r-th tile (r < TP) in the order of i + j, then i: its index i TB + j.
  function automatic int tile_at(input int r);
    int n;
    n       = 0;
    tile_at = 0;
    for (int d = 0; d < TA + TB - 1; d++) begin
      for (int i = 0; i < TA; i++) begin
        if (d - i >= 0 && d - i < TB) begin
          if (n == r) tile_at = i * TB + d - i;
          n = n + 1;
        end
      end
    end
  endfunction
  // The first r on diagonal d: the tiles of the diagonals below it.
  function automatic int diag_start(input int d);
    diag_start = 0;
    for (int e = 0; e < d; e++) begin
      for (int i = 0; i < TA; i++) begin
        if (e - i >= 0 && e - i < TB) diag_start = diag_start + 1;
      end
    end
  endfunction
  // The diagonal of the r-th tile; a zero tile (r >= TP) counts as the last tile's.
  function automatic int diag_at(input int r);
    diag_at = tile_at((r < TP) ? r : TP - 1) / TB + tile_at((r < TP) ? r : TP - 1) % TB;
  endfunction
  // Whether step s of a multiplier whose first chunk is k0 starts a diagonal inside its chunk.
  function automatic bit starts_diag(input int s, input int k0);
    starts_diag = s % H != 0 && step_r(s, k0) < TP
                  && diag_at(step_r(s, k0)) != diag_at(step_r(s, k0) - 1);
  endfunction

  if (N < 1 || ABits < 2 || BBits < 2 || SetupII < 2) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: N >= 1, ABits and BBits >= 2 and SetupII >= 2")
  end
  if (TA > 4 && TB > 4) begin : gen_acc_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: at most four tiles a diagonal (min(TA, TB) <= 4)")
  end
  if (Stages < 0 || Stages > 1 || (Stages == 0 && Q != 1)) begin : gen_stages_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: Stages is 1, or 0 where every product is one chunk (TA TB <= SetupII - FmulOverhead)")
  end
  if (P < 1) begin : gen_slot_check
    `SPEC_PARAM_ERROR("specular_setup_fmul: half a product's tiles must fit the slot (TA TB <= 2 (SetupII - FmulOverhead))")
  end

  // The slot's clock count, and the same one-hot (at_q[c]: clock c of the slot): the
  // accumulators' enables are its flip-flops, or registers set from it a clock ahead, not
  // decodes of the count (the decode of a clear, shared by the merge across units, and its
  // route to every accumulator's synchronous reset in one clock were the system's critical
  // path at SetupII = 16, docs/setup_hw.md#the-folded-setup).
  logic [CW-1:0]      cnt_q;
  logic [SetupII-1:0] at_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      cnt_q <= '0;
      at_q  <= SetupII'(1);
    end else if (cnt_q < CW'(SetupII - 1)) begin
      cnt_q <= cnt_q + CW'(1);
      at_q  <= at_q << 1;
    end
  end

  // The operands' tiles, each T bits signed: tile i of a is bits (T-1) i .. (T-1) i + T - 2
  // zero-extended, the top one sign-extended.
  logic [N*TA*T-1:0] atile;
  logic [N*TB*T-1:0] btile;
  for (genvar j = 0; j < N; j++) begin : gen_tiles
    logic [TA*(T-1)+1-1:0] a_ext;
    logic [TB*(T-1)+1-1:0] b_ext;
    assign a_ext = (TA * (T - 1) + 1)'($signed(a_i[j*ABits +: ABits]));
    assign b_ext = (TB * (T - 1) + 1)'($signed(b_i[j*BBits +: BBits]));
    for (genvar i = 0; i < TA; i++) begin : gen_a
      if (i == TA - 1) begin : gen_top
        assign atile[(j*TA+i)*T +: T] = a_ext[i*(T-1) +: T];
      end else begin : gen_low
        assign atile[(j*TA+i)*T +: T] = {1'b0, a_ext[i*(T-1) +: T-1]};
      end
    end
    for (genvar i = 0; i < TB; i++) begin : gen_b
      if (i == TB - 1) begin : gen_top
        assign btile[(j*TB+i)*T +: T] = b_ext[i*(T-1) +: T];
      end else begin : gen_low
        assign btile[(j*TB+i)*T +: T] = {1'b0, b_ext[i*(T-1) +: T-1]};
      end
    end
  end

  // Chunk k is part k % Q of product k / Q: tiles (k % Q) H .. (k % Q) H + H - 1 (a tile
  // index from TP on is a zero tile). Tile t is (t / TB, t % TB), weight 2^((T-1)(t / TB + t % TB)).
  logic [N*Q*PBits-1:0] csum;
  for (genvar m = 0; m < M; m++) begin : gen_mult
    localparam int K0    = m * P;                              // its first chunk
    localparam int Pm    = (N * Q - K0 < P) ? N * Q - K0 : P;  // its chunks
    localparam int Steps = Pm * H;
    // Its tiles: chunk l's a tiles at l TA + i, b tiles at l TB + i.
    logic [Pm*TA*T-1:0] asrc;
    logic [Pm*TB*T-1:0] bsrc;
    for (genvar l = 0; l < Pm; l++) begin : gen_src
      assign asrc[l*TA*T +: TA*T] = atile[((K0 + l) / Q)*TA*T +: TA*T];
      assign bsrc[l*TB*T +: TB*T] = btile[((K0 + l) / Q)*TB*T +: TB*T];
    end
    // The tile selects: a decode of the slot count for a few steps, a one-hot token for many
    // (each is the smaller there in the ECP5 synthesis). nd_d (this step starts a diagonal) is
    // decoded with them and travels beside the tile and its product: the accumulator's shift
    // select is then a register, not a decode of the count shared by every multiplier and
    // routed across the unit (docs/setup_hw.md#the-folded-setup).
    logic signed [T-1:0] ta_d, tb_d;
    logic                nd_d, nd1_q, nd2_q;
    if (Steps > TokenMinSteps) begin : gen_token
      // c = s: a one-hot token marks step s (set by the advance, shifted out after the last
      // step). Each tile's select is a register, the OR of its steps' token bits a clock
      // ahead (step 0's set by the advance itself), and the tile registers take the AND-OR of
      // the selected tiles (no decode of the count, no priority chain). Registered, a select
      // leaves a flip-flop straight for its multiplexers: the merge makes one register of the
      // units' identical selects, and a select decoded from the token in the same clock was a
      // gate shared by units across the part, two long routes in one clock
      // (docs/setup_hw.md#the-folded-setup).
      logic [Steps-1:0]  tok_q;
      always_ff @(posedge clk_i) begin
        if (en_i) tok_q <= Steps'(1);
        else      tok_q <= tok_q << 1;
      end
      logic [Pm*TA-1:0] sel_a, sel_a_d;
      logic [Pm*TB-1:0] sel_b, sel_b_d;
      logic             nd_n;
      always_comb begin
        sel_a_d = '0;
        sel_b_d = '0;
        nd_n    = 1'b0;
        for (int s = 0; s < Steps; s++) begin
          // Step s comes next: the advance (s = 0) or the token on step s - 1.
          if (starts_diag(s, K0)) nd_n |= (s == 0) ? en_i : (!en_i && tok_q[(s > 0) ? s - 1 : 0]);
          if (step_r(s, K0) < TP) begin
            sel_a_d[(s / H) * TA + tile_at(step_r(s, K0)) / TB] |= (s == 0) ? en_i : (!en_i && tok_q[(s > 0) ? s - 1 : 0]);
            sel_b_d[(s / H) * TB + tile_at(step_r(s, K0)) % TB] |= (s == 0) ? en_i : (!en_i && tok_q[(s > 0) ? s - 1 : 0]);
          end
        end
      end
      always_ff @(posedge clk_i) begin
        sel_a <= sel_a_d;
        sel_b <= sel_b_d;
        nd_d  <= nd_n;
      end
      always_comb begin
        ta_d = '0;
        tb_d = '0;
        for (int i = 0; i < Pm * TA; i++) begin
          ta_d = ta_d | ({T{sel_a[i]}} & asrc[i*T +: T]);
        end
        for (int i = 0; i < Pm * TB; i++) begin
          tb_d = tb_d | ({T{sel_b[i]}} & bsrc[i*T +: T]);
        end
      end
    end else begin : gen_decode
      localparam int IAW = $clog2(Pm * TA + 1);
      localparam int IBW = $clog2(Pm * TB + 1);
      // c = s: decode step s (narrow signals), load its tiles.
      logic [IAW-1:0] ia;
      logic [IBW-1:0] ib;
      logic           zero;
      always_comb begin
        ia    = '0;
        ib    = '0;
        zero  = 1'b1;
        nd_d  = 1'b0;
        for (int s = 0; s < Steps; s++) begin
          if (32'(cnt_q) == s) begin
            ia    = IAW'((s / H) * TA + tile_at(step_r(s, K0) % TP) / TB);
            ib    = IBW'((s / H) * TB + tile_at(step_r(s, K0) % TP) % TB);
            zero  = step_r(s, K0) >= TP;
            nd_d  = starts_diag(s, K0);
          end
        end
      end
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
    end
    // c = s and c = 1 + s above: the DSP's own input and product registers
    // (rtl/prim/specular_mul_tile.sv).
    logic signed [2*T-1:0] pp_q;
    specular_mul_tile #(.Bits (T), .Signed (1'b1)) u_tile (
      .clk_i (clk_i),
      .en_i  (1'b1),
      .a_i   (ta_d),
      .b_i   (tb_d),
      .p_o   (pp_q)
    );
    always_ff @(posedge clk_i) begin
      nd1_q <= nd_d;
      nd2_q <= nd1_q;
    end
    // c = 2 + s: accumulate step s; when its tile starts a diagonal, the accumulator's low
    // T - 1 bits (the diagonal below, final) go to a segment register and the rest moves
    // down. A chunk's last step writes the finished top into the chunk's register and clears
    // the accumulator (a synchronous reset, no multiplexer in front of the adder); the last
    // chunk's top stays in the accumulator until the slot's first clock clears it.
    logic signed [AccW-1:0] acc_q, acc_d;
    always_comb begin
      acc_d = (nd2_q ? (acc_q >>> (T - 1)) : acc_q) + AccW'(pp_q);
    end
    // acc_clr_q: clock 0 or (l + 1) H + 1 comes next; acc_en_q: clocks 2 .. Steps + 1 (each
    // before the slot's last, Steps <= SetupII - FmulOverhead).
    logic acc_clr_q, acc_en_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        acc_clr_q <= 1'b1;
        acc_en_q  <= 1'b0;
      end else begin
        acc_clr_q <= 1'b0;
        for (int l = 0; l < Pm - 1; l++) begin
          if (at_q[(l + 1) * H]) acc_clr_q <= 1'b1;
        end
        if (at_q[1]) acc_en_q <= 1'b1;
        else if (at_q[Steps + 1]) acc_en_q <= 1'b0;
      end
    end
    always_ff @(posedge clk_i) begin
      if (acc_clr_q) begin
        acc_q <= '0;
      end else if (acc_en_q) begin
        acc_q <= acc_d;
      end
    end
    for (genvar l = 0; l < Pm; l++) begin : gen_chunk
      localparam int R0   = step_r(l * H, K0);   // its first tile
      localparam int D0   = diag_at(R0);          // its first and last diagonals
      localparam int DL   = diag_at(R0 + H - 1);
      localparam int NSeg = DL - D0;              // the diagonals it finishes below its top
      logic signed [AccW-1:0] top;
      if (l == Pm - 1) begin : gen_last
        assign top = acc_q;
      end else begin : gen_res
        logic signed [AccW-1:0] top_q;
        always_ff @(posedge clk_i) begin
          if (at_q[(l + 1) * H + 1]) top_q <= acc_d;
        end
        assign top = top_q;
      end
      // Its value modulo 2^PBits (exact, as the product fits): top, segments, zeros below. A
      // narrow product leaves the top's upper bits unread.
      logic unused_top;
      assign unused_top = ^top;
      if (NSeg == 0) begin : gen_top_only
        assign csum[(K0 + l)*PBits +: PBits] = PBits'(top) << ((T - 1) * D0);
      end else begin : gen_segs
        // Segment e: diagonal D0 + e, written where diagonal D0 + e + 1 starts.
        logic [NSeg*(T-1)-1:0] seg_q;
        for (genvar e = 0; e < NSeg; e++) begin : gen_seg
          localparam int SE = l * H + (diag_start(D0 + e + 1) - R0);  // that step
          always_ff @(posedge clk_i) begin
            if (at_q[SE + 2]) seg_q[e*(T-1) +: T-1] <= acc_q[T-2:0];
          end
        end
        assign csum[(K0 + l)*PBits +: PBits] = (PBits'(top) << ((T - 1) * DL))
                                              | (PBits'(seg_q) << ((T - 1) * D0));
      end
    end
  end

  // The product: its chunks summed (one carry chain).
  logic [N*PBits-1:0] p_d;
  for (genvar j = 0; j < N; j++) begin : gen_prod
    if (Q == 1) begin : gen_one
      assign p_d[j*PBits +: PBits] = csum[j*PBits +: PBits];
    end else begin : gen_two
      assign p_d[j*PBits +: PBits] = csum[2*j*PBits +: PBits] + csum[(2*j+1)*PBits +: PBits];
    end
  end

  assign pc_o = p_d;
  if (Stages == 1) begin : gen_p_reg
    always_ff @(posedge clk_i) begin
      if (en_i) p_o <= p_d;
    end
  end else begin : gen_p_wire
    assign p_o = p_d;
  end

endmodule
