// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Pipelined unsigned multiplier p = a * b, exact, for the LUT fabric of an iCE40 (no DSP
// needed), one new operand pair every clock, en_i freezes every stage (pipeline stall).
// No reset: the datapath carries no control state, the valid bits beside it are reset.
//
// b is taken two bits at a time; each digit selects 0, a, 2a or 3a (a3_i, which the caller
// computes a clock earlier, off this pipeline's path). The first stage only registers the
// selected rows (a multiplexer, no carry chain: an AND in front of the first adder would
// put logic before its carry chain, on the longest path), then a binary tree of adders with
// a register after every level
// adds them, so no stage holds more than one carry chain. Stages:
// specular_pkg::pipe_mul_stages(BBits) = 1 + clog2(ceil(BBits / 2)) (docs/pipeline.md#stage-counts);
// the block checks at elaboration that the tree it builds has that many levels.
// Used by multiplier 11 (coef * |psi|), the ROM 12 interpolation (t * d) and
// multiplier 13 (C * cos^k) of patent UA 71489.
//
// TileBits picks the resources (docs/pipeline.md#multiplier-styles): 0 is the LUT tree above,
// for a part without DSPs (the iCE40-HX8K); 16 (the UP5K's SB_MAC16) or 18 (the ECP5's
// MULT18X18D) delay a and b by the clocks the shorter tree leaves over, cut them into
// TileBits-wide tiles, register the tiles and each tile product (one DSP with its input and
// output registers, rtl/prim/specular_mul_tile.sv) and add the products in a registered
// binary tree: the same
// pipe_mul_stages(BBits) clocks, so both styles are bit-exact
// and interchangeable. a3_i is unused there (a caller may tie it to 0). The
// tiles must be few enough that 2 + clog2(tiles) <= pipe_mul_stages(BBits); the block refuses
// otherwise. Signed = 1 (DSP tiles only) takes a_i and b_i as signed and gives the signed
// product: unsigned low tiles of TileBits - 1 bits and a signed top tile, so every tile product
// is one signed TileBits x TileBits product and the rows add as they are (the setup's
// products, rtl/setup/specular_setup_smul.sv).

`include "specular_assert.svh"

module specular_pipe_mul #(
  parameter int ABits    = 16,
  parameter int BBits    = 16,
  parameter int TileBits = 0,   // 0: LUT tree; else the DSP tile width (16 UP5K, 18 ECP5)
  parameter bit Signed   = 1'b0 // signed operands and product (DSP tiles only)
) (
  input  logic                   clk_i,
  input  logic                   en_i,
  input  logic [ABits-1:0]       a_i,
  input  logic [ABits+1:0]       a3_i,    // 3 * a_i
  input  logic [BBits-1:0]       b_i,
  output logic [ABits+BBits-1:0] p_o
);

  localparam bit Tree   = TileBits == 0;
  localparam int PBits  = ABits + BBits;
  localparam int Levels = specular_pkg::pipe_mul_stages(BBits);
  localparam int TilesA = Tree ? 1 : Signed ? specular_pkg::signed_tiles(ABits, TileBits)
                                            : (ABits + TileBits - 1) / TileBits;
  localparam int TilesB = Tree ? 1 : Signed ? specular_pkg::signed_tiles(BBits, TileBits)
                                            : (BBits + TileBits - 1) / TileBits;
  // A tile's step: its width, or the low tiles' TileBits - 1 when signed.
  localparam int Step   = (Signed && !Tree) ? TileBits - 1 : TileBits;
  // The bits of tile i (of n) of a width-bit operand that are its own, the rest being zero
  // (unsigned) or copies of the sign (signed): a low tile's all (signed, its top bit is a 0
  // that is not the sign's copy), the top tile's those of the operand.
  function automatic int tile_live(input int width, input int n, input int i);
    tile_live = (i < n - 1) ? TileBits : width - i * Step;
  endfunction
  // Rows into the adder tree: the radix-4 digit rows, or the tile products.
  localparam int NRows  = Tree ? (BBits + 1) / 2 : TilesA * TilesB;
  // Level 1 registers the rows, the levels after it halve them until one is left. The DSP
  // style registers the tile operands first (the DSP's input registers: a ROM or a carry
  // chain in front of a multiplier would otherwise share its stage), after its operands have
  // waited out Levels - AddLevels clocks.
  localparam int TreeLevels = 1 + ((NRows > 1) ? $clog2(NRows) : 0);
  localparam int AddLevels  = TreeLevels + (Tree ? 0 : 1);

  // (BBits = 1 needs no multiplier; from 2 on every digit row fits the product's width.)
  if (ABits < 1 || BBits < 2) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_pipe_mul: ABits must be >= 1 and BBits >= 2")
  end
  if (Tree && Levels != TreeLevels) begin : gen_levels_check
    `SPEC_PARAM_ERROR("specular_pipe_mul: specular_pkg::pipe_mul_stages disagrees with the tree built here")
  end
  if (TileBits < 0 || TileBits == 1 || AddLevels > Levels) begin : gen_tile_check
    `SPEC_PARAM_ERROR("specular_pipe_mul: TileBits must be 0 or >= 2, with 2 + clog2(tiles) <= pipe_mul_stages(BBits)")
  end
  if (Signed && Tree) begin : gen_signed_check
    `SPEC_PARAM_ERROR("specular_pipe_mul: Signed needs DSP tiles (TileBits > 0)")
  end

  // rows[l][j]: row j after level l; level 0 is combinational.
  logic [PBits-1:0] rows [TreeLevels+1][NRows];

  if (!Tree) begin : gen_tiles
    logic unused_a3;
    assign unused_a3 = ^a3_i;
    // The DSP style's tree is shorter than the radix-4 one: the operands wait out the
    // difference before their tiles (where operands that several products share are the same
    // registers, which a synthesis can merge; the sum is a product's own).
    logic [ABits-1:0] a_al;
    logic [BBits-1:0] b_al;
    specular_delay #(.Width (ABits + BBits), .Depth (Levels - AddLevels), .Reset (1'b0)) u_align (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({a_i, b_i}), .q_o ({a_al, b_al}));
    // Tile i of an operand: TileBits bits from bit i Step; signed, the low tiles are the
    // TileBits - 1 bits zero-extended and the top tile the rest sign-extended.
    logic [TilesA*TileBits-1:0] a_tiles;
    logic [TilesB*TileBits-1:0] b_tiles;
    if (Signed) begin : gen_signed_tiles
      logic [TilesA*Step:0] a_ext;
      logic [TilesB*Step:0] b_ext;
      assign a_ext = (TilesA * Step + 1)'($signed(a_al));
      assign b_ext = (TilesB * Step + 1)'($signed(b_al));
      for (genvar i = 0; i < TilesA; i++) begin : gen_ta
        assign a_tiles[i*TileBits +: TileBits] = (i == TilesA - 1) ? a_ext[i*Step +: TileBits]
                                                                   : {1'b0, a_ext[i*Step +: Step]};
      end
      for (genvar j = 0; j < TilesB; j++) begin : gen_tb
        assign b_tiles[j*TileBits +: TileBits] = (j == TilesB - 1) ? b_ext[j*Step +: TileBits]
                                                                   : {1'b0, b_ext[j*Step +: Step]};
      end
    end else begin : gen_unsigned_tiles
      assign a_tiles = (TilesA * TileBits)'(a_al);
      assign b_tiles = (TilesB * TileBits)'(b_al);
    end
    for (genvar i = 0; i < TilesA; i++) begin : gen_a
      for (genvar j = 0; j < TilesB; j++) begin : gen_b
        // Tile registers, product and product register: level 1 of the tree. Below the
        // diagonal the operands go in swapped, so that a square's tiles (i, j) and (j, i) are
        // one cell with the same inputs, which the merge of identical cells shares
        // (rtl/fpga/README.md#merged-cells; Yosys orders a $mul's inputs, not a primitive's).
        localparam bit Swap = i > j;
        logic [2*TileBits-1:0] tp;
        specular_mul_tile #(
          .Bits   (TileBits),
          .Signed (Signed),
          .ALive  (Swap ? tile_live(BBits, TilesB, j) : tile_live(ABits, TilesA, i)),
          .BLive  (Swap ? tile_live(ABits, TilesA, i) : tile_live(BBits, TilesB, j))
        ) u_tile (
          .clk_i (clk_i),
          .en_i  (en_i),
          .a_i   (Swap ? b_tiles[j*TileBits +: TileBits] : a_tiles[i*TileBits +: TileBits]),
          .b_i   (Swap ? a_tiles[i*TileBits +: TileBits] : b_tiles[j*TileBits +: TileBits]),
          .p_o   (tp)
        );
        if (Signed) begin : gen_signed_tp
          // Modulo 2^PBits the rows add to the exact product, which fits PBits signed bits.
          logic signed [PBits+2*TileBits-1:0] tp_x;
          assign tp_x = (PBits + 2 * TileBits)'($signed(tp));
          assign rows[1][i*TilesB+j] = PBits'(tp_x <<< ((i + j) * Step));
        end else begin : gen_unsigned_tp
          // The padding tiles' bits are 0, so every product fits the PBits of a * b.
          assign rows[1][i*TilesB+j] = PBits'({{PBits{1'b0}}, tp} << ((i + j) * TileBits));
        end
      end
    end
    for (genvar j = 0; j < NRows; j++) begin : gen_no_rows0
      assign rows[0][j] = '0;
    end
  end else begin : gen_digits
    logic [2*NRows-1:0] b_pad;
    assign b_pad = (2 * NRows)'(b_i);
    for (genvar j = 0; j < NRows; j++) begin : gen_pp
      logic [1:0]       digit;
      logic [ABits+1:0] digit_row;
      assign digit = b_pad[2*j +: 2];  // Icarus 11: no constant part select in always_comb
      always_comb begin
        unique case (digit)
          2'd0:    digit_row = '0;
          2'd1:    digit_row = (ABits + 2)'(a_i);
          2'd2:    digit_row = (ABits + 2)'(a_i) << 1;
          default: digit_row = a3_i;
        endcase
      end
      assign rows[0][j] = PBits'(digit_row) << (2 * j);
    end
  end

  // Level 1 of the DSP style is the tiles' product registers (above); the tree's own
  // registers start at level 1 for the radix-4 rows and at level 2 for the tiles.
  for (genvar l = Tree ? 1 : 2; l <= TreeLevels; l++) begin : gen_level
    // Level 1 registers the rows as they are; later levels add pairs.
    localparam bit Adds  = l != 1;
    localparam int Shift = l - 1;   // additions done up to this level
    localparam int NPrev = Adds ? (NRows + (1 << (Shift - 1)) - 1) >> (Shift - 1) : NRows;
    localparam int NCur  = (NRows + (1 << Shift) - 1) >> Shift;
    for (genvar j = 0; j < NCur; j++) begin : gen_row
      logic [PBits-1:0] sum, sum_q;
      if (!Adds) begin : gen_copy
        assign sum = rows[l-1][j];
      end else if (2 * j + 1 < NPrev) begin : gen_add
        assign sum = rows[l-1][2*j] + rows[l-1][2*j+1];
      end else begin : gen_pass
        assign sum = rows[l-1][2*j];
      end
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          sum_q <= sum;
        end
      end
      // rows is driven by continuous assignments only (Icarus 11 cannot mix them with
      // procedural writes to other words of the same array).
      assign rows[l][j] = sum_q;
    end
    // Rows beyond NCur are not used at this level.
    for (genvar j = NCur; j < NRows; j++) begin : gen_unused_row
      assign rows[l][j] = '0;
    end
  end

  assign p_o = rows[TreeLevels][0];

  // Assertions (rtl/prim/specular_assert.svh): the caller's 3a matches a (it registers both,
  // from the same a, on the same enable). No reset here: checked from the first enabled edge
  // on (before it the caller's registers hold power-up values) and on known operands (a
  // bubble's may be X). The DSP style reads no 3a, so a caller may tie it off there.
`ifndef SYNTHESIS
  if (Tree) begin : gen_a3_check
    `SPEC_PRIMED(primed_q, clk_i, en_i)
    logic a_known;
    assign a_known = `SPEC_KNOWN({a_i, a3_i});
    `SPEC_ASSERT_IF(A3IsThreeA_A, en_i && a_known, a3_i == (ABits + 2)'(a_i) * (ABits + 2)'(3), clk_i, primed_q)
  end
`endif

endmodule
