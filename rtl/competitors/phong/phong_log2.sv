// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// w = -log2 c of phong_stream's textbook form (docs/phong_hw.md#design) by an interpolated log2
// ROM; phong_exp2 then raises it to n and scales it. Bit-exact contract (every shift and
// rounding): model/device/phong_model.hpp. phong_pkg::log2_stages(LogFracBits) stages:
//   1        e: c = 2^-e mant (priority encoder); c = 1
//   2        mant's fraction bits (shift)
//   3        the log2 ROM read {v, dv}; the weight t
//   ..       dv * t (phong_mul)
//   +1 .. +3 rounding; v + step; w = e - log2 mant (one carry chain each)

`include "specular_assert.svh"

module phong_log2 #(
  parameter int CosFrac     = 23,
  parameter int LogAddrBits = 9,
  parameter int LogFracBits = 13,
  parameter int LogBits     = 21,
  parameter     LogRomFile  = "",
  // 0: LUT-tree multipliers; 16 / 18: DSP tiles (docs/pipeline.md#multiplier-styles)
  parameter int MulTileBits = 0,
  // bit_width(CosFrac + 1) + LogBits: the largest w, c >= 2^-CosFrac
  localparam int WBits      = $clog2(CosFrac + 2) + LogBits
) (
  input  logic              clk_i,
  input  logic              en_i,
  input  logic [CosFrac:0]  c_i,
  output logic [WBits-1:0]  w_o
);

  localparam int EBits      = $clog2(CosFrac + 1);
  localparam int LogDBits   = LogBits - LogAddrBits + 1;
  localparam int MulL       = phong_pkg::mul_stages(LogFracBits);

  if (LogAddrBits + LogFracBits > CosFrac || LogFracBits < 2 ||
      phong_pkg::log2_stages(LogFracBits) != 3 + MulL + 3) begin : gen_param_check
    `SPEC_PARAM_ERROR("phong_log2: the table fields exceed their words, or phong_pkg disagrees")
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
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      r_4   <= lp + (LogDBits + LogFracBits)'(1 << (LogFracBits - 1));
      v_4   <= v_m;
      e_4   <= e_m;
      one_4 <= one_m;
      lg_5  <= (LogBits + 1)'(v_4) + (LogBits + 1)'(r_4 >> LogFracBits);
      e_5   <= e_4;
      one_5 <= one_4;
      w_o   <= one_5 ? '0 : (WBits'(e_5) << LogBits) - WBits'(lg_5);
    end
  end

endmodule
