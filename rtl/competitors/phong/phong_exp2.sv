// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// The power and the scale of both forms of phong_stream (docs/phong_hw.md#design):
// I = scale * 2^(-n w) from w = -log2 cos (WBits, LogBits fraction bits), by the product
// z = n w and an interpolated exp2 ROM. Bit-exact contract: model/device/phong_model.hpp.
// phong_pkg::exp2_stages(WBits, ExpFracBits, ExpBits) stages:
//   ..       z = n * w (phong_mul)
//   +1       the exp2 ROM read {u, du}; the weight t; zi > ExpBits
//   ..       du * t (phong_mul)
//   +1 .. +3 rounding; u - step; the shift by zi
//   ..       scale * p (phong_mul)
//   last     rounding to the format of C, 0 for a zero pixel

`include "specular_assert.svh"

module phong_exp2 #(
  parameter int WBits       = 26,
  parameter int LogBits     = 21,
  parameter int ExpAddrBits = 5,
  parameter int ExpFracBits = 7,
  parameter int ExpBits     = 16,
  parameter int NBits       = 10,
  parameter int CBits       = 16,
  parameter     ExpRomFile  = "",
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0
) (
  input  logic              clk_i,
  input  logic              en_i,
  input  logic [WBits-1:0]  w_i,
  input  logic              zero_i,
  input  logic [NBits-1:0]  n_i,
  input  logic [CBits-1:0]  scale_i,
  output logic [CBits-1:0]  intensity_o
);

  localparam int ZBits    = NBits + WBits;
  localparam int ExpDBits = ExpBits - ExpAddrBits;
  localparam int ShBits   = $clog2(ExpBits + 1);
  localparam int MulW     = phong_pkg::mul_stages(WBits);
  localparam int MulE     = phong_pkg::mul_stages(ExpFracBits);
  localparam int MulS     = phong_pkg::mul_stages(ExpBits + 1);

  if (WBits <= LogBits || ExpAddrBits + ExpFracBits > LogBits || ExpFracBits < 2 ||
      phong_pkg::exp2_stages(WBits, ExpFracBits, ExpBits) != MulW + 1 + MulE + 3 + MulS + 1) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_exp2: WBits > LogBits, the table fields within LogBits; phong_pkg disagrees")
  end

  // ---- z = n * w ----
  logic [ZBits-1:0] z;
  phong_mul #(.ABits (NBits), .BBits (WBits), .TileBits (MulTileBits)) u_mul_z (
    .clk_i (clk_i), .en_i (en_i), .a_i (n_i), .b_i (w_i), .p_o (z));
  logic [CBits-1:0] scale_z;
  logic             zero_z;
  specular_delay #(.Width (CBits + 1), .Depth (MulW), .Reset (1'b0)) u_z_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({scale_i, zero_i}), .q_o ({scale_z, zero_z}));

  // ---- exp2 ROM, du * t ----
  logic [ExpBits+1+ExpDBits-1:0] xw_7;
  logic [ExpFracBits-1:0]        t_7;
  logic [ShBits-1:0]             zi_7;
  logic                          big_7, zero_7;
  logic [CBits-1:0]              scale_7;
  logic [ZBits-LogBits-1:0]      zi;
  assign zi = z[ZBits-1:LogBits];
  specular_rom #(
    .Width    (ExpBits + 1 + ExpDBits),
    .AddrBits (ExpAddrBits),
    .File     (ExpRomFile)
  ) u_exp_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (z[LogBits-1 -: ExpAddrBits]),
    .data_o (xw_7)
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      t_7     <= z[LogBits-ExpAddrBits-1 -: ExpFracBits];
      zi_7    <= ShBits'(zi);
      big_7   <= 32'(zi) > ExpBits;
      zero_7  <= zero_z;
      scale_7 <= scale_z;
    end
  end
  if (LogBits > ExpAddrBits + ExpFracBits) begin : gen_unused_z
    logic unused_z;
    assign unused_z = ^z[LogBits-ExpAddrBits-ExpFracBits-1:0];
  end

  logic [ExpDBits+ExpFracBits-1:0] xp;
  phong_mul #(.ABits (ExpDBits), .BBits (ExpFracBits), .TileBits (MulTileBits)) u_mul_exp (
    .clk_i (clk_i), .en_i (en_i), .a_i (xw_7[ExpDBits-1:0]), .b_i (t_7), .p_o (xp));
  logic [ExpBits:0]   u_m;
  logic [ShBits-1:0]  zi_m;
  logic               big_m, zero_m;
  logic [CBits-1:0]   scale_m;
  specular_delay #(.Width (ExpBits + 1 + ShBits + 2 + CBits), .Depth (MulE), .Reset (1'b0)) u_exp_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({xw_7[ExpDBits +: ExpBits + 1], zi_7, big_7, zero_7, scale_7}),
    .q_o ({u_m, zi_m, big_m, zero_m, scale_m}));

  logic [ExpDBits+ExpFracBits-1:0] r_8;
  logic [ExpBits:0]                u_8, p_9, p_10;
  logic [ShBits-1:0]               zi_8, zi_9;
  logic                            zero_8, zero_9, zero_10;
  logic [CBits-1:0]                scale_8, scale_9, scale_10;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      r_8      <= xp + (ExpDBits + ExpFracBits)'(1 << (ExpFracBits - 1));
      u_8      <= u_m;
      zi_8     <= zi_m;
      zero_8   <= zero_m | big_m;
      scale_8  <= scale_m;
      p_9      <= u_8 - (ExpBits + 1)'(r_8 >> ExpFracBits);
      zi_9     <= zi_8;
      zero_9   <= zero_8;
      scale_9  <= scale_8;
      p_10     <= p_9 >> zi_9;
      zero_10  <= zero_9;
      scale_10 <= scale_9;
    end
  end

  // ---- scale * p, rounding ----
  logic [CBits+ExpBits:0] sp;
  phong_mul #(.ABits (CBits), .BBits (ExpBits + 1), .TileBits (MulTileBits)) u_mul_scale (
    .clk_i (clk_i), .en_i (en_i), .a_i (scale_10), .b_i (p_10), .p_o (sp));
  logic zero_s;
  specular_delay #(.Width (1), .Depth (MulS), .Reset (1'b0)) u_zero_s (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (zero_10), .q_o (zero_s));
  logic [CBits+ExpBits:0] rounded;
  assign rounded = sp + (CBits + ExpBits + 1)'(1 << (ExpBits - 1));
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      intensity_o <= zero_s ? '0 : rounded[ExpBits +: CBits];
    end
  end
  logic unused_r;
  assign unused_r = ^{rounded[ExpBits-1:0], rounded[CBits+ExpBits]};

endmodule
