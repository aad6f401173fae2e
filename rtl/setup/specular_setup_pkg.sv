// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_pkg: the widths, constants and stage counts of the hardware setup
// (rtl/setup/specular_setup.sv, docs/setup_hw.md) at the golden model's unit width F = 26
// (host::fixed::kFrac, model/host/setup_fixed.hpp, where each is defined). The lines holding
// the model's values are printed by `build/bin/setup_romgen --consts`, and ctest
// rtl_setup_pkg (setup_romgen --check-pkg) fails if one differs. The tables are ROM files
// (roms/setup/).
//
// Written for Yosys 0.23, Verilator 5.006 and Icarus 11 alike (as specular_pkg): functions
// return through their name, no local variables; callers write specular_setup_pkg::f(...).

// The linter (Verilator) elaborates every package of rtl/specular.f for any top level; built for a top
// without the setup (specular_stream, a block test) it would call every constant unused.
/* verilator lint_off UNUSEDPARAM */
package specular_setup_pkg;

  // The register formats of the descriptor the setup writes: specular_stream's defaults
  // (device::Format in model/device/device_model.hpp), which the golden model requires. The
  // setup and its formal harness take their port widths from here.
  localparam int SpanCBits     = 16;
  localparam int SpanAngleBits = 32;
  localparam int SpanNBits     = 10;
  localparam int SpanLenBits   = 11;

  // ---- The model's widths and constants (setup_romgen --consts) ----
  localparam int Frac = 26;
  localparam int SeedAddrBits = 9;
  localparam int SeedInterpBits = 9;
  localparam int SeedFrac = 18;
  localparam int SeedWords = 385;
  localparam int FlatLog2 = 44;
  localparam int OppHalfLog2 = 20;
  localparam int OppNormLog2 = 12;
  localparam int RsqrtInBits = 30;
  localparam int RsqrtFrac = 28;
  localparam int BlockBits = 28;
  localparam int CordicFrac = 29;
  localparam int CordicIters = 28;
  localparam int CordicW = 34;
  localparam int GammaFrac = 30;
  localparam int RecipLenFrac = 31;
  localparam int LogFrac = 30;
  localparam int LogUnitFrac = 44;
  localparam logic signed [63:0] Pi = 64'sd1686629713;

  // ---- Widths of the datapath (derived; each holds its value with margin) ----
  localparam int SeedW  = SeedFrac + 2;  // seed words in (2^18, 2^19]: 20 bits, unsigned
  localparam int UnitW  = Frac + 2;      // unit vectors, Q26: |value| < 2
  localparam int BlkW   = BlockBits + 2; // block-normalized: |value| <= 2^28
  localparam int RW     = Frac + 6;      // 1/sqrt, Q28 in (1, 2]
  localparam int A2W    = 2 * Frac + 3;  // A^2, Q52: < 2 (Cauchy-Schwarz and rounding)
  localparam int AngleBits = 32;         // psi0, dpsi (device::Format)
  localparam int AngleFrac = 28;

  // round(atan(2^-i) 2^CordicFrac): atan_q50's words rounded half up (fixed::atan_word).
  function automatic logic signed [63:0] atan_word(input int i);
    case (i)
      0: atan_word = 64'sd421657428;
      1: atan_word = 64'sd248918915;
      2: atan_word = 64'sd131521918;
      3: atan_word = 64'sd66762579;
      4: atan_word = 64'sd33510843;
      5: atan_word = 64'sd16771758;
      6: atan_word = 64'sd8387925;
      7: atan_word = 64'sd4194219;
      8: atan_word = 64'sd2097141;
      9: atan_word = 64'sd1048575;
      10: atan_word = 64'sd524288;
      11: atan_word = 64'sd262144;
      12: atan_word = 64'sd131072;
      13: atan_word = 64'sd65536;
      14: atan_word = 64'sd32768;
      15: atan_word = 64'sd16384;
      16: atan_word = 64'sd8192;
      17: atan_word = 64'sd4096;
      18: atan_word = 64'sd2048;
      19: atan_word = 64'sd1024;
      20: atan_word = 64'sd512;
      21: atan_word = 64'sd256;
      22: atan_word = 64'sd128;
      23: atan_word = 64'sd64;
      24: atan_word = 64'sd32;
      25: atan_word = 64'sd16;
      26: atan_word = 64'sd8;
      27: atan_word = 64'sd4;
      default: atan_word = 64'sd0;
    endcase
  endfunction

  // ---- The folded products (SetupII > 1, specular_setup_fmul) ----
  // Clocks of a slot that are not tile steps: the tile product register, the last
  // accumulation and the advance edge (p_o).
  localparam int FmulOverhead = 3;
  // The widest product's tiles (35 x 52 bits, 2 x 3).
  localparam int WidestTiles = 6;
  // The smallest folding: the widest product in two chunks of three tile steps each.
  localparam int MinFoldII = FmulOverhead + WidestTiles / 2;
  // From this folding on every product is one chunk, so a unit's pc_o is its chunk registers
  // with no adder behind them, final before the slot's last clock: the product's consumer
  // reads it there and registers its own result on the advance, and the product takes no
  // stage of its own (no p_o register, docs/setup_hw.md#the-folded-setup). Below it a
  // product takes one stage (p_o, after the sum of its two chunks).
  localparam int OneChunkII = FmulOverhead + WidestTiles;
  function automatic int fold_mul_stages(input int setup_ii);
    fold_mul_stages = (setup_ii >= OneChunkII) ? 0 : 1;
  endfunction
  // The signed tile width: the DSP's (18) or, for the LUT style, the same 18. An operand is
  // cut into unsigned low tiles of fmul_tile - 1 bits and a signed top tile.
  function automatic int fmul_tile(input int tile_bits);
    fmul_tile = (tile_bits == 0) ? 18 : tile_bits;
  endfunction
  // Tiles of a w-bit signed operand.
  function automatic int fmul_tiles_of(input int w, input int tile_bits);
    fmul_tiles_of = specular_pkg::signed_tiles(w, fmul_tile(tile_bits));
  endfunction
  // Tile products of one a_bits x b_bits product.
  function automatic int fmul_tiles(input int a_bits, input int b_bits, input int tile_bits);
    fmul_tiles = fmul_tiles_of(a_bits, tile_bits) * fmul_tiles_of(b_bits, tile_bits);
  endfunction
  // Tile steps of a multiplier in a slot of setup_ii clocks.
  function automatic int fmul_steps(input int setup_ii);
    fmul_steps = setup_ii - FmulOverhead;
  endfunction
  // Chunks of a product: 1, or 2 (on two multipliers, summed at the end) when its tiles do not
  // fit one multiplier's slot.
  function automatic int fmul_split(input int a_bits, input int b_bits, input int tile_bits,
                                    input int setup_ii);
    fmul_split = (fmul_tiles(a_bits, b_bits, tile_bits) > fmul_steps(setup_ii)) ? 2 : 1;
  endfunction
  // Tile steps of one chunk (the second of an odd split has one zero tile).
  function automatic int fmul_chunk(input int a_bits, input int b_bits, input int tile_bits,
                                    input int setup_ii);
    fmul_chunk = (fmul_tiles(a_bits, b_bits, tile_bits) + fmul_split(a_bits, b_bits, tile_bits, setup_ii) - 1)
               / fmul_split(a_bits, b_bits, tile_bits, setup_ii);
  endfunction
  // Chunks one multiplier finishes in a slot (whole chunks only).
  function automatic int fmul_per_mult(input int a_bits, input int b_bits, input int tile_bits,
                                       input int setup_ii);
    fmul_per_mult = fmul_steps(setup_ii) / fmul_chunk(a_bits, b_bits, tile_bits, setup_ii);
  endfunction
  // Multipliers of a unit of n products: the DSP count falls as setup_ii grows.
  function automatic int fmul_mults(input int n, input int a_bits, input int b_bits,
                                    input int tile_bits, input int setup_ii);
    fmul_mults = (n * fmul_split(a_bits, b_bits, tile_bits, setup_ii)
                  + fmul_per_mult(a_bits, b_bits, tile_bits, setup_ii) - 1)
               / fmul_per_mult(a_bits, b_bits, tile_bits, setup_ii);
  endfunction

  // ---- Stage counts ----
  // specular_pipe_mul's stages for a BBits-wide multiplier operand (specular_pkg::pipe_mul_stages).
  function automatic int pipe_mul_stages(input int b_bits);
    pipe_mul_stages = 1 + ((((b_bits + 1) / 2) > 1) ? $clog2((b_bits + 1) / 2) : 0);
  endfunction
  // specular_setup_smul (signed, B bits): magnitudes, 3|a|, the multiplier, the sign. With
  // SetupII > 1 a product is one slot's work of a specular_setup_fmul: fold_mul_stages.
  function automatic int smul_stages(input int b_bits, input int setup_ii);
    smul_stages = (setup_ii > 1) ? fold_mul_stages(setup_ii) : 3 + pipe_mul_stages(b_bits);
  endfunction
  // specular_setup_norm for InW-bit components (the module checks its own count).
  function automatic int norm_stages(input int in_w, input int setup_ii);
    norm_stages = smul_stages(in_w, setup_ii) + 6 + smul_stages(SeedW + 1, setup_ii) + 2
                + smul_stages(SeedW + 1, setup_ii) + 1
                + smul_stages(2 * SeedW - (2 * SeedFrac - RsqrtFrac) + 2, setup_ii) + 2
                + smul_stages(RsqrtFrac + 5, setup_ii) + 1 + smul_stages(RW, setup_ii) + 2;
  endfunction

  localparam int BlockStages  = 4;                // specular_setup_block
  localparam int CordicStages = 1 + CordicIters;  // specular_setup_cordic
  // Folded (SetupII > 1) a CORDIC is a specular_setup_cordic_fold, cordic_segs segments of
  // cordic_rounds iterations, two clocks an iteration: a segment starts on its slot's first
  // clock and its 2 Rounds clocks end before the slot's last, on whose advance the last
  // segment's angle is registered (2 Rounds <= setup_ii - 2). The CORDIC takes cordic_segs
  // stages.
  function automatic int cordic_rounds(input int setup_ii);
    cordic_rounds = ((setup_ii - 2) / 2 < CordicIters) ? (setup_ii - 2) / 2 : CordicIters;
  endfunction
  function automatic int cordic_segs(input int setup_ii);
    cordic_segs = (CordicIters + cordic_rounds(setup_ii) - 1) / cordic_rounds(setup_ii);
  endfunction
  function automatic int cordic_stages(input int setup_ii);
    cordic_stages = (setup_ii > 1) ? cordic_segs(setup_ii) : CordicStages;
  endfunction

  // ---- log2 and exp2 (specular_setup_log2, specular_setup_exp2), the 1/l table ----
  localparam int LogW          = LogFrac + 8;       // log2 A: |value| < 128
  localparam int ExpW          = LogFrac + 18;      // n log2 A: |value| < 2^17
  localparam int AmpW          = LogUnitFrac + 4;   // log2's input, Q44: 0 <= value < 8
  localparam int LogAddrBits   = 10;
  localparam int LogRecipFrac  = 12;
  // log2(1 + e) = e (L1 + e (L2 + e L3)), 2^f = 1 + f (E1 + f (E2 + f E3)), Q30
  localparam logic signed [63:0] L1 = 64'sd1549082005;
  localparam logic signed [63:0] L2 = -64'sd774541002;
  localparam logic signed [63:0] L3 = 64'sd516360668;
  localparam logic signed [63:0] E1 = 64'sd744261118;
  localparam logic signed [63:0] E2 = 64'sd257941248;
  localparam logic signed [63:0] E3 = 64'sd59597083;
  localparam int LogStages    = 6;                // specular_setup_log2: A -> log2 A
  localparam int ExpStages    = 8;                // specular_setup_exp2: n log2 A -> C

  // ---- The arctangent table every CORDIC rounds its words from: Q50, 48 words; pi in Q50 ----
  localparam int AtanFrac = 50;
  localparam int AtanIters = 48;
  localparam logic signed [63:0] PiQ50 = 64'sd3537118876014220;
  // round(atan(2^-i) 2^50); from i = 17 on it is 2^(50 - i) exactly.
  function automatic logic signed [63:0] atan_q50(input int i);
    case (i)
      0:  atan_q50 = 64'sd884279719003555;
      1:  atan_q50 = 64'sd522020799781813;
      2:  atan_q50 = 64'sd275821453992967;
      3:  atan_q50 = 64'sd140011276775614;
      4:  atan_q50 = 64'sd70277332359676;
      5:  atan_q50 = 64'sd35172925548918;
      6:  atan_q50 = 64'sd17590754598329;
      7:  atan_q50 = 64'sd8795914071791;
      8:  atan_q50 = 64'sd4398024141687;
      9:  atan_q50 = 64'sd2199020459356;
      10: atan_q50 = 64'sd1099511278251;
      11: atan_q50 = 64'sd549755770197;
      12: atan_q50 = 64'sd274877901483;
      13: atan_q50 = 64'sd137438952789;
      14: atan_q50 = 64'sd68719476651;
      15: atan_q50 = 64'sd34359738357;
      16: atan_q50 = 64'sd17179869183;
      default: atan_q50 = 64'sd1 <<< (AtanFrac - i);
    endcase
  endfunction

  // Round half up: (x + 2^(s-1)) >> s for s >= 1 (arithmetic), x << -s for s <= 0.
  // Every product of the setup is exact in 128 bits and rounded once by this.
  function automatic logic signed [127:0] rshift_round(input logic signed [127:0] x, input int s);
    if (s <= 0) begin
      rshift_round = x <<< (-s);
    end else begin
      rshift_round = (x + (128'sd1 <<< (s - 1))) >>> s;
    end
  endfunction


  // The same in 64 bits, for the products that stay below 2^63 (log2, exp2, dpsi, A): Verilator
  // keeps them in 64-bit words. Callers pass narrow signals sign-extended, so synthesis sizes
  // the multiplier by the signals' widths.
  function automatic logic signed [63:0] rshift_round64(input logic signed [63:0] x, input int s);
    if (s <= 0) begin
      rshift_round64 = x <<< (-s);
    end else begin
      rshift_round64 = (x + (64'sd1 <<< (s - 1))) >>> s;
    end
  endfunction
  // The addend that rounds and adds in one carry chain: rshift_round64(x, s) + k equals
  // (x + round_addend(k, s)) >>> s for s >= 1 (k 2^s is a multiple of 2^s), a constant when
  // k is (log2's and exp2's Horner steps).
  function automatic logic signed [63:0] round_addend(input logic signed [63:0] k, input int s);
    round_addend = (k <<< s) + (64'sd1 <<< (s - 1));
  endfunction
  function automatic logic signed [63:0] mul64(input logic signed [63:0] a, input logic signed [63:0] b);
    mul64 = a * b;
  endfunction

endpackage
/* verilator lint_on UNUSEDPARAM */
