// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Multiplier 13 of patent UA 71489 and the output register (output 27):
//   I = (C * cosk + 2^(CosDataBits-1)) >> CosDataBits
// C from register 1 (unsigned, CBits bits, this pixel's span), cosk from ROM 12
// (CosDataBits fraction bits, at most 1.0), so I has the format of C, cannot overflow, and
// cosk = 1.0 gives I = C exactly. zero_i forces 0: a pixel flagged zero (far angle,
// zeta >= pi/2, invalid n), or no pixel at all (a pipeline bubble), so the output reads 0
// whenever no pixel is valid.
// Pipeline, every register enabled by en_i (stall): the radix-4 multiplier tree
// (specular_pipe_mul over the bits of cos^k) with the zero flag beside it, then the rounding
// and the output register: specular_pkg::intensity_mul_stages clocks
// (docs/pipeline.md#stage-counts).

`include "specular_assert.svh"

module specular_intensity_mul #(
  parameter int CBits       = 16,
  parameter int CosDataBits = 18,
  parameter int MulTileBits = 0    // specular_pipe_mul's TileBits: 0 LUT tree, 16 / 18 DSP tiles
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 en_i,      // pipeline advance (clock enable)
  input  logic [CBits-1:0]     c_i,       // register 1 (this pixel's span)
  input  logic [CBits+1:0]     c3_i,      // 3 C, computed when the span was accepted
  input  logic [CosDataBits:0] cosk_i,    // ROM 12
  input  logic                 zero_i,
  output logic [CBits-1:0]     intensity_o
);

  if (CosDataBits < 1 || CBits < 1) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_intensity_mul: widths must be >= 1")
  end

  localparam int ProdBits  = CBits + CosDataBits + 1;
  // Radix-4 tree over the bits of cos^k (specular_pipe_mul), C and 3C as the multiplicand.
  localparam int MulStages = specular_pkg::pipe_mul_stages(CosDataBits + 1);
  if (specular_pkg::Mul13OutStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_intensity_mul: builds one output register behind the tree (specular_pkg)")
  end

  logic [ProdBits-1:0] prod;
  specular_pipe_mul #(
    .ABits    (CBits),
    .BBits    (CosDataBits + 1),
    .TileBits (MulTileBits)
  ) u_tree (
    .clk_i (clk_i),
    .en_i  (en_i),
    .a_i   (c_i),
    .a3_i  (c3_i),
    .b_i   (cosk_i),
    .p_o   (prod)
  );

  // The flag travels as "keep" so that the reset state (0) zeroes the output: the tree
  // registers have no reset and hold garbage until the first pixel passes.
  logic keep_m;
  specular_delay #(.Width (1), .Depth (MulStages)) u_keep (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (en_i), .d_i (~zero_i), .q_o (keep_m));

  logic [ProdBits-1:0] prod_rnd;
  assign prod_rnd = prod + (ProdBits'(1) << (CosDataBits - 1));   // round half up

  logic [CBits-1:0] intensity_d, intensity_q;
  // C * cosk <= C * 2^CosDataBits, so the rounded quotient fits CBits.
  assign intensity_d = keep_m ? prod_rnd[CosDataBits +: CBits] : '0;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      intensity_q <= '0;
    end else if (en_i) begin
      intensity_q <= intensity_d;
    end
  end

  assign intensity_o = intensity_q;

  // The discarded low product bits are the rounding remainder; the top bit is 0 (see above).
  logic unused_prod_bits;
  assign unused_prod_bits = ^{prod_rnd[CosDataBits-1:0], prod_rnd[ProdBits-1]};

  // Assertions (rtl/prim/specular_assert.svh): cos^k of a pixel that is not zero is at most 1.0
  // (so I <= C and the top product bit is 0) and known, as are C and 3 C beside it; the
  // output is never X.
  `SPEC_ASSERT_IF(CoskAtMostOne_A, en_i && !zero_i, cosk_i <= (CosDataBits + 1)'(1 << CosDataBits), clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(OperandsKnown_A, {c_i, c3_i, cosk_i}, en_i && !zero_i, clk_i, rst_ni)
  `SPEC_ASSERT(TopBitZero_A, keep_m == 1'b0 || prod_rnd[ProdBits-1] == 1'b0, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(IntensityKnown_A, intensity_o, clk_i, rst_ni)

endmodule
