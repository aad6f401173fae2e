// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// The power and the scale of phong_stream (docs/phong_hw.md#design): I = scale * 2^(-n w),
// w = -log2 c, by an interpolated log2 ROM, the product n w and an interpolated exp2 ROM.
// Bit-exact contract (every shift and rounding): model/device/phong_model.hpp.
// phong_pkg::pow_stages(LogFracBits, WBits, ExpFracBits, ExpBits) stages:
//   1        e: c = 2^-e mant (priority encoder); c = 1
//   2        mant's fraction bits (shift)
//   3        the log2 ROM read {v, dv}; the weight t
//   ..       dv * t (phong_mul)
//   +1 .. +3 rounding; v + step; w = e - log2 mant (one carry chain each)
//   ..       z = n * w (phong_mul)
//   +1       the exp2 ROM read {u, du}; the weight t; zi > ExpBits
//   ..       du * t (phong_mul)
//   +1 .. +3 rounding; u - step; the shift by zi
//   ..       scale * p (phong_mul)
//   last     rounding to the format of C, 0 for a zero pixel

`include "specular_assert.svh"

module phong_pow #(
  parameter int CosFrac     = 23,
  parameter int LogAddrBits = 9,
  parameter int LogFracBits = 13,
  parameter int LogBits     = 21,
  parameter int ExpAddrBits = 5,
  parameter int ExpFracBits = 7,
  parameter int ExpBits     = 16,
  parameter int NBits       = 10,
  parameter int CBits       = 16,
  parameter     LogRomFile  = "",
  parameter     ExpRomFile  = "",
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0
) (
  input  logic              clk_i,
  input  logic              en_i,
  input  logic [CosFrac:0]  c_i,
  input  logic              zero_i,
  input  logic [NBits-1:0]  n_i,
  input  logic [CBits-1:0]  scale_i,
  output logic [CBits-1:0]  intensity_o
);

  localparam int EBits      = $clog2(CosFrac + 1);
  localparam int WBits      = $clog2(CosFrac + 2) + LogBits;  // bit_width(CosFrac + 1) + LogBits
  localparam int ZBits      = NBits + WBits;
  localparam int LogDBits   = LogBits - LogAddrBits + 1;
  localparam int ExpDBits   = ExpBits - ExpAddrBits;
  localparam int ShBits     = $clog2(ExpBits + 1);
  localparam int MulL       = phong_pkg::mul_stages(LogFracBits);
  localparam int MulW       = phong_pkg::mul_stages(WBits);
  localparam int MulE       = phong_pkg::mul_stages(ExpFracBits);
  localparam int MulS       = phong_pkg::mul_stages(ExpBits + 1);

  if (LogAddrBits + LogFracBits > CosFrac || ExpAddrBits + ExpFracBits > LogBits || LogFracBits < 2 ||
      ExpFracBits < 2 || phong_pkg::pow_stages(LogFracBits, WBits, ExpFracBits, ExpBits)
                         != 3 + MulL + 3 + MulW + 1 + MulE + 3 + MulS + 1) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_pow: the table fields exceed their words, or phong_pkg disagrees")
  end

  // ---- stage 1: the exponent of c ----
  function automatic logic [EBits-1:0] lead_exp(input logic [CosFrac:0] x);
    lead_exp = '0;
    for (int b = 0; b < CosFrac; b++) begin
      if (x[b]) lead_exp = EBits'(CosFrac - b);
    end
  endfunction

  logic [CosFrac:0] c_1;
  logic [EBits-1:0] e_1;
  logic             one_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      c_1   <= c_i;
      e_1   <= lead_exp(c_i);
      one_1 <= c_i[CosFrac];
    end
  end

  // ---- stage 2: mant's fraction ----
  logic [CosFrac-1:0] frac_2;
  logic [EBits-1:0]   e_2;
  logic               one_2;
  logic [CosFrac:0]   cs;
  assign cs = c_1 << e_1;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      frac_2 <= cs[CosFrac-1:0];
      e_2    <= e_1;
      one_2  <= one_1;
    end
  end
  logic unused_cs;
  assign unused_cs = cs[CosFrac];

  // ---- stage 3: log2 ROM ----
  logic [LogBits+LogDBits-1:0] lw_3;
  logic [LogFracBits-1:0]      t_3;
  logic [EBits-1:0]            e_3;
  logic                        one_3;
  specular_rom #(
    .Width    (LogBits + LogDBits),
    .AddrBits (LogAddrBits),
    .File     (LogRomFile)
  ) u_log_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (frac_2[CosFrac-1 -: LogAddrBits]),
    .data_o (lw_3)
  );
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      t_3   <= frac_2[CosFrac-LogAddrBits-1 -: LogFracBits];
      e_3   <= e_2;
      one_3 <= one_2;
    end
  end
  if (CosFrac > LogAddrBits + LogFracBits) begin : gen_unused_frac
    logic unused_frac;
    assign unused_frac = ^frac_2[CosFrac-LogAddrBits-LogFracBits-1:0];
  end

  // ---- dv * t, then v + round(dv t), w ----
  logic [LogDBits+LogFracBits-1:0] lp;
  phong_mul #(.ABits (LogDBits), .BBits (LogFracBits), .TileBits (MulTileBits)) u_mul_log (
    .clk_i (clk_i), .en_i (en_i), .a_i (lw_3[LogDBits-1:0]), .b_i (t_3), .p_o (lp));
  logic [LogBits-1:0] v_m;
  logic [EBits-1:0]   e_m;
  logic               one_m;
  specular_delay #(.Width (LogBits + EBits + 1), .Depth (MulL), .Reset (1'b0)) u_log_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({lw_3[LogDBits +: LogBits], e_3, one_3}),
    .q_o ({v_m, e_m, one_m}));

  logic [LogDBits+LogFracBits-1:0] r_4;
  logic [LogBits-1:0]              v_4;
  logic [EBits-1:0]                e_4, e_5;
  logic                            one_4, one_5;
  logic [LogBits:0]                lg_5;
  logic [WBits-1:0]                w_6;
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      r_4   <= lp + (LogDBits + LogFracBits)'(1 << (LogFracBits - 1));
      v_4   <= v_m;
      e_4   <= e_m;
      one_4 <= one_m;
      lg_5  <= (LogBits + 1)'(v_4) + (LogBits + 1)'(r_4 >> LogFracBits);
      e_5   <= e_4;
      one_5 <= one_4;
      w_6   <= one_5 ? '0 : (WBits'(e_5) << LogBits) - WBits'(lg_5);
    end
  end

  // ---- z = n * w ----
  logic [NBits-1:0] n_w;
  logic [CBits-1:0] scale_w;
  logic             zero_w;
  localparam int ToW = 3 + MulL + 3;
  specular_delay #(.Width (NBits + CBits + 1), .Depth (ToW), .Reset (1'b0)) u_n_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({n_i, scale_i, zero_i}), .q_o ({n_w, scale_w, zero_w}));
  logic [ZBits-1:0] z;
  phong_mul #(.ABits (NBits), .BBits (WBits), .TileBits (MulTileBits)) u_mul_z (
    .clk_i (clk_i), .en_i (en_i), .a_i (n_w), .b_i (w_6), .p_o (z));
  logic [CBits-1:0] scale_z;
  logic             zero_z;
  specular_delay #(.Width (CBits + 1), .Depth (MulW), .Reset (1'b0)) u_z_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({scale_w, zero_w}), .q_o ({scale_z, zero_z}));

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
