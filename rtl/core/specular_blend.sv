// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_blend: the display-exact device's blend of two ROM 12 reads (docs/display_exact.md),
// between ROM 12 and multiplier 13. For reads c1 (decoder 10's bank) and c2 (the next bank),
// each 0 where its zero flag is set (past its bank's domain, or the pixel is 0), and the weight
// w of the second bank (WeightBits, from ROM 9):
//   cos_b = c1 + ((c2 - c1) * w + 2^(W-1)) >> W     (arithmetic shift: floor; W = WeightBits)
// bit-identical to device::DeviceModel::trace. cos_b lies between c1 and c2, so it keeps their
// CosDataBits + 1 bits.
//
// How, without a signed multiplier (the iCE40's LUT tree is unsigned): the difference is
// offset to u = c2 - c1 + 2^(D+1) in [2^D, 3 2^D] (D = CosDataBits: flip the top bit of the
// (D + 2)-bit difference), the tree forms w * u, and a register beside it holds
// c1 2^W + 2^(W-1) - w 2^(D+1); their sum is c1 2^W + (c2 - c1) w + 2^(W-1), of which cos_b is
// bits W .. W + D. Every sum is taken modulo 2^(D + 1 + W), which holds the result.
//
// Pipeline, every register enabled by en_i (specular_pkg::blend_stages, docs/pipeline.md#stage-counts):
//   in     the reads zeroed by their flags (a synchronous clear, no logic before a carry chain)
//   diff   u = c2 - c1 + 2^(D+1); 3 w for the radix-4 tree; c1 and w beside
//   tree   specular_pipe_mul: w * u over the D + 2 bits of u; beside it c1 2^W + 2^(W-1) - w 2^(D+1)
//   out    cos_b = (that + w u) >> W
// No reset: the datapath carries no control state (the valid bits beside it are reset).

`include "specular_assert.svh"

module specular_blend #(
  parameter int CosDataBits = 18,
  parameter int WeightBits  = 12,
  parameter int MulTileBits = 0    // specular_pipe_mul's TileBits: 0 LUT tree, 16 / 18 DSP tiles
) (
  input  logic                  clk_i,
  input  logic                  en_i,      // pipeline advance (clock enable)
  input  logic [CosDataBits:0]  c1_i,      // read 1 (decoder 10's bank), at most 2^CosDataBits
  input  logic [CosDataBits:0]  c2_i,      // read 2 (the next bank)
  input  logic                  zero1_i,   // read 1 is 0
  input  logic                  zero2_i,   // read 2 is 0
  input  logic [WeightBits-1:0] w_i,       // weight of read 2, w / 2^WeightBits
  output logic [CosDataBits:0]  cosb_o     // cos_b, CosDataBits fraction bits
);

  localparam int D         = CosDataBits;
  localparam int W         = WeightBits;
  localparam int UBits     = D + 2;
  localparam int SumBits   = D + 1 + W;
  localparam int MulStages = specular_pkg::pipe_mul_stages(UBits);

  if (D < 1 || W < 1) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_blend: CosDataBits and WeightBits must be >= 1")
  end
  if (specular_pkg::BlendInStages != 1 || specular_pkg::BlendDiffStages != 1 ||
      specular_pkg::BlendOutStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_blend: builds one input, one difference and one output register (specular_pkg)")
  end

  // ---- in: each read zeroed by its flag
  logic [D:0]   c1_q, c2_q;
  logic [W-1:0] w_q;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      c1_q <= zero1_i ? '0 : c1_i;
      c2_q <= zero2_i ? '0 : c2_i;
      w_q  <= w_i;
    end
  end

  // ---- diff: the offset difference u, 3 w, c1 and w beside
  logic [UBits-1:0] diff, u_q;
  logic [D:0]       c1_d;
  logic [W-1:0]     w_d;
  logic [W+1:0]     w3_d;
  assign diff = UBits'(c2_q) - UBits'(c1_q);
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      u_q  <= {~diff[UBits-1], diff[UBits-2:0]};   // + 2^(D+1) modulo 2^(D+2)
      c1_d <= c1_q;
      w_d  <= w_q;
      w3_d <= (W + 2)'(w_q) + ((W + 2)'(w_q) << 1);
    end
  end

  // ---- tree: w * u, and beside it c1 2^W + 2^(W-1) - w 2^(D+1)
  logic [W+UBits-1:0] prod;
  specular_pipe_mul #(
    .ABits    (W),
    .BBits    (UBits),
    .TileBits (MulTileBits)
  ) u_weight (
    .clk_i (clk_i),
    .en_i  (en_i),
    .a_i   (w_d),
    .a3_i  (w3_d),
    .b_i   (u_q),
    .p_o   (prod)
  );

  logic [SumBits-1:0] base_q, base_m;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      base_q <= {c1_d, W'(1) << (W - 1)} - (SumBits'(w_d) << (D + 1));
    end
  end
  specular_delay #(.Width (SumBits), .Depth (MulStages - 1), .Reset (1'b0)) u_base (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (base_q), .q_o (base_m));

  // ---- out: cos_b
  logic [SumBits-1:0] sum;
  logic [D:0]         cosb_q;
  assign sum = base_m + SumBits'(prod);
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      cosb_q <= sum[W +: D + 1];
    end
  end
  assign cosb_o = cosb_q;

  logic unused_bits;
  assign unused_bits = ^{sum[W-1:0], prod[W+UBits-1:SumBits]};

  // Assertions (rtl/prim/specular_assert.svh): the reads are at most 1.0, so the offset
  // difference stays in [2^D, 3 2^D] and cos_b, between them, at most 1.0. No reset here:
  // checked from the first enabled edge on and on known values (a bubble's may be X).
`ifndef SYNTHESIS
  // The registers hold power-up values until the first enabled edges have filled them: the
  // input register after one, the output after every stage (fill_q, a shift of enabled edges).
  localparam int Fill = specular_pkg::BlendInStages + specular_pkg::BlendDiffStages + MulStages
                        + specular_pkg::BlendOutStages;
  `SPEC_PRIMED(primed_q, clk_i, en_i)
  logic [Fill-1:0] fill_q = '0;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      fill_q <= {fill_q[Fill-2:0], 1'b1};
    end
  end
  logic in_known, out_known;
  assign in_known  = `SPEC_KNOWN({c1_q, c2_q});
  assign out_known = `SPEC_KNOWN(cosb_q);
  `SPEC_ASSERT_IF(ReadsAtMostOne_A, en_i && in_known,
                  c1_q <= (D + 1)'(1) << D && c2_q <= (D + 1)'(1) << D, clk_i, primed_q)
  `SPEC_ASSERT_IF(CosbAtMostOne_A, out_known, cosb_q <= (D + 1)'(1) << D, clk_i, fill_q[Fill-1])
`endif

endmodule
