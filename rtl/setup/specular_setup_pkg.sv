// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_pkg: the widths, constants and stage counts of the hardware setup
// (rtl/setup/specular_setup.sv, docs/setup_hw.md#widths). The widths and constants are those of
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

  // The register formats of the descriptor the setup writes: specular_stream's defaults
  // (device::Format in model/device/device_model.hpp), which the golden model requires. The
  // setup and its formal harness take their port widths from here.
  localparam int SpanCBits     = 16;
  localparam int SpanAngleBits = 32;
  localparam int SpanNBits     = 10;
  localparam int SpanLenBits   = 11;

  // ---- Widths (setup_fixed.hpp) ----
  localparam int UnitFrac      = 44;  // unit vectors, dot products, A: Q44
  localparam int VecW          = UnitFrac + 4;  // a Q44 vector component (|value| < 8)
  localparam int RsqrtInBits   = UnitFrac + 2;  // normalized radicand in [2^44, 2^46)
  localparam int RsqrtFrac     = UnitFrac;      // 1/sqrt, Q44
  localparam int RsqrtAddrBits = 12;  // seed table address (3072 words)
  localparam int RsqrtSeedFrac = 16;  // seed words, Q16 (17 bits)
  localparam int CordicFrac    = UnitFrac + 6;  // CORDIC x, y, angles: Q50
  localparam int CordicIters   = UnitFrac + 4;
  localparam int CordicW       = CordicFrac + 4;  // CORDIC x, y, z: |value| < 8
  localparam int GammaFrac     = 30;  // gamma for the product with 1/l: Q30
  localparam int GainFrac      = 30;  // A K and 1/K for their product: Q30
  localparam int LogFrac       = 30;  // log2 A, n log2 A, 2^f: Q30
  localparam int LogW          = LogFrac + 8;   // log2 A: |value| < 128
  localparam int ExpW          = LogFrac + 18;  // n log2 A: |value| < 2^17
  localparam int AmpW          = UnitFrac + 4;  // A, Q44: 0 <= value < 8
  localparam int LogAddrBits   = 10;
  localparam int LogRecipFrac  = 12;
  localparam int RecipLenFrac  = 31;  // 1/l mantissa round(2^(31 + s) / l), s = floor(log2 l)
  localparam int ChordFloor    = 16;  // Q44 codes: the flat and opposite-halfway floor

  // ---- Constants (setup_romgen --consts) ----
  localparam logic signed [63:0] InvGain = 64'sd652032874;       // round(2^30 / K)
  localparam logic signed [63:0] Pi      = 64'sd3537118876014220;  // round(pi 2^50)
  // log2(1 + e) = e (L1 + e (L2 + e L3)), 2^f = 1 + f (E1 + f (E2 + f E3)), Q30
  localparam logic signed [63:0] L1 = 64'sd1549082005;
  localparam logic signed [63:0] L2 = -64'sd774541002;
  localparam logic signed [63:0] L3 = 64'sd516360668;
  localparam logic signed [63:0] E1 = 64'sd744261118;
  localparam logic signed [63:0] E2 = 64'sd257941248;
  localparam logic signed [63:0] E3 = 64'sd59597083;

  // ---- Stage counts (each block checks its own at elaboration) ----
  localparam int NormStages   = 9;                // specular_setup_norm
  localparam int CordicStages = 1 + CordicIters;  // specular_setup_cordic: half turn + iterations
  localparam int LogStages    = 6;                // specular_setup_log2: A -> log2 A
  localparam int ExpStages    = 8;                // specular_setup_exp2: n log2 A -> C

  // round(atan(2^-i) 2^50); from i = 17 on it is 2^(50 - i) exactly.
  function automatic logic signed [63:0] atan_q(input int i);
    case (i)
      0:  atan_q = 64'sd884279719003555;
      1:  atan_q = 64'sd522020799781813;
      2:  atan_q = 64'sd275821453992967;
      3:  atan_q = 64'sd140011276775614;
      4:  atan_q = 64'sd70277332359676;
      5:  atan_q = 64'sd35172925548918;
      6:  atan_q = 64'sd17590754598329;
      7:  atan_q = 64'sd8795914071791;
      8:  atan_q = 64'sd4398024141687;
      9:  atan_q = 64'sd2199020459356;
      10: atan_q = 64'sd1099511278251;
      11: atan_q = 64'sd549755770197;
      12: atan_q = 64'sd274877901483;
      13: atan_q = 64'sd137438952789;
      14: atan_q = 64'sd68719476651;
      15: atan_q = 64'sd34359738357;
      16: atan_q = 64'sd17179869183;
      default: atan_q = 64'sd1 <<< (CordicFrac - i);
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
