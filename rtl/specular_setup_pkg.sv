// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_pkg: the widths, constants and stage counts of the hardware setup
// (rtl/specular_setup.sv, docs/setup_hw.md#widths). The widths and constants are those of
// the golden model, model/host/setup_fixed.hpp, where each is defined and documented; the
// constants are printed by `build/bin/setup_romgen --consts` and the bit-exact block test
// (tests/rtl/test_setup.cpp) fails if one differs. The tables are ROM files (roms/setup/).
//
// Written for Yosys 0.23, Verilator 5.006 and Icarus 11 alike (as specular_pkg): functions
// return through their name; callers write specular_setup_pkg::f(...).

// The linter (Verilator) elaborates every package of rtl/specular.f for any top level; built for a top
// without the setup (specular_stream, a block test) it would call every constant unused.
/* verilator lint_off UNUSEDPARAM */
package specular_setup_pkg;

  // ---- Widths (setup_fixed.hpp) ----
  localparam int UnitFrac      = 44;  // unit vectors, dot products, A: Q44
  localparam int VecW          = 48;  // a Q44 vector component (|value| < 8)
  localparam int RsqrtInBits   = 48;  // normalized radicand in [2^46, 2^48)
  localparam int RsqrtFrac     = 48;  // 1/sqrt, Q48
  localparam int RsqrtAddrBits = 12;  // seed table address (3072 words)
  localparam int RsqrtSeedFrac = 16;  // seed words, Q16 (17 bits)
  localparam int CordicFrac    = 48;  // CORDIC x, y, angles: Q48
  localparam int CordicIters   = 48;
  localparam int LogFrac       = 40;  // log2 A, n log2 A, 2^f: Q40
  localparam int LogAddrBits   = 10;
  localparam int LogRecipFrac  = 12;
  localparam int RecipLenFrac  = 50;
  localparam int ChordFloor    = 16;  // Q44 codes: the flat and opposite-halfway floor

  // ---- Constants (setup_romgen --consts) ----
  localparam logic signed [63:0] InvGain = 64'sd170926505739102;  // round(2^48 / K)
  localparam logic signed [63:0] PiQ48   = 64'sd884279719003555;  // round(pi 2^48)
  // log2(1 + e) = e (L1 + e (L2 + e L3)), 2^f = 1 + f (E1 + f (E2 + f E3)), Q40
  localparam logic signed [63:0] L1 = 64'sd1586259972792;
  localparam logic signed [63:0] L2 = -64'sd793129986396;
  localparam logic signed [63:0] L3 = 64'sd528753324264;
  localparam logic signed [63:0] E1 = 64'sd762123384786;
  localparam logic signed [63:0] E2 = 64'sd264131837702;
  localparam logic signed [63:0] E3 = 64'sd61027412866;

  // ---- Stage counts (each block checks its own at elaboration) ----
  localparam int NormStages   = 9;                // specular_setup_norm
  localparam int CordicStages = 1 + CordicIters;  // specular_setup_cordic: half turn + iterations
  localparam int LogStages    = 5;                // specular_setup_log2: A -> log2 A
  localparam int ExpStages    = 6;                // specular_setup_exp2: n log2 A -> C

  // round(atan(2^-i) 2^48); from i = 16 on it is 2^(48 - i) exactly.
  function automatic logic signed [63:0] atan_q48(input int i);
    case (i)
      0:  atan_q48 = 64'sd221069929750889;
      1:  atan_q48 = 64'sd130505199945453;
      2:  atan_q48 = 64'sd68955363498242;
      3:  atan_q48 = 64'sd35002819193903;
      4:  atan_q48 = 64'sd17569333089919;
      5:  atan_q48 = 64'sd8793231387230;
      6:  atan_q48 = 64'sd4397688649582;
      7:  atan_q48 = 64'sd2198978517948;
      8:  atan_q48 = 64'sd1099506035422;
      9:  atan_q48 = 64'sd549755114839;
      10: atan_q48 = 64'sd274877819563;
      11: atan_q48 = 64'sd137438942549;
      12: atan_q48 = 64'sd68719475371;
      13: atan_q48 = 64'sd34359738197;
      14: atan_q48 = 64'sd17179869163;
      15: atan_q48 = 64'sd8589934589;
      default: atan_q48 = 64'sd1 <<< (CordicFrac - i);
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

  // Exact product of two Q-values, sign-extended to 128 bits.
  function automatic logic signed [127:0] mul(input logic signed [63:0] a, input logic signed [63:0] b);
    mul = 128'(a) * 128'(b);
  endfunction

endpackage
/* verilator lint_on UNUSEDPARAM */
