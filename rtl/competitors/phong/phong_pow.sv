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
//   ..       phong_exp2: z = n w, 2^-z, scale 2^-z (phong_pkg::exp2_stages)

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
  localparam int LogDBits   = LogBits - LogAddrBits + 1;
  localparam int MulL       = phong_pkg::mul_stages(LogFracBits);

  if (LogAddrBits + LogFracBits > CosFrac || LogFracBits < 2 ||
      phong_pkg::pow_stages(LogFracBits, WBits, ExpFracBits, ExpBits)
        != 3 + MulL + 3 + phong_pkg::exp2_stages(WBits, ExpFracBits, ExpBits)) begin : gen_param_check
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

  // ---- the power and the scale: phong_exp2, the span's values beside w ----
  logic [NBits-1:0] n_w;
  logic [CBits-1:0] scale_w;
  logic             zero_w;
  specular_delay #(.Width (NBits + CBits + 1), .Depth (3 + MulL + 3), .Reset (1'b0)) u_n_side (
    .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i ({n_i, scale_i, zero_i}), .q_o ({n_w, scale_w, zero_w}));
  phong_exp2 #(
    .WBits       (WBits),
    .LogBits     (LogBits),
    .ExpAddrBits (ExpAddrBits),
    .ExpFracBits (ExpFracBits),
    .ExpBits     (ExpBits),
    .NBits       (NBits),
    .CBits       (CBits),
    .ExpRomFile  (ExpRomFile),
    .MulTileBits (MulTileBits)
  ) u_exp2 (
    .clk_i       (clk_i),
    .en_i        (en_i),
    .w_i         (w_6),
    .zero_i      (zero_w),
    .n_i         (n_w),
    .scale_i     (scale_w),
    .intensity_o (intensity_o)
  );

endmodule
