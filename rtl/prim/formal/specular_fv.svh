// SPDX-License-Identifier: Apache-2.0
//
// What the formal harnesses share, written once.
//
// `SPECULAR_FV_PARAMS: the reduced core parameters, the core's list of
// rtl/core/specular_params.svh with small widths (the proofs unroll every register), two
// decoder banks, the ROM files of this folder (docs/formal.md), and TagBits 2. A
// harness hands them on to its core with `SPECULAR_CORE_PARAM_MAP.

`ifndef SPECULAR_FV_SVH
`define SPECULAR_FV_SVH

`define SPECULAR_FV_PARAMS \
  parameter int CBits        = 4, \
  parameter int CFrac        = 3, \
  parameter int AngleBits    = 8, \
  parameter int AngleFrac    = 4, \
  parameter int AccBits      = 12, \
  parameter int NBits        = 4, \
  parameter int LenBits      = 3, \
  parameter int CoefBits     = 4, \
  parameter int CoefFrac     = 2, \
  parameter int PsiMulFrac   = 2, \
  parameter bit CosInterp    = 1'b0, \
  parameter int CosAddrBits  = 2, \
  parameter int CosDataBits  = 4, \
  parameter int CosDeltaBits = 4, \
  parameter int CosFracBits  = 1, \
  parameter int NumBanks     = 2, \
  parameter logic [NumBanks*NBits-1:0] BankMaxN = {4'd15, 4'd1}, \
  parameter bit Blend        = 1'b0, \
  parameter int WeightBits   = 12, \
  parameter int Channels     = 1, \
  parameter int MulTileBits  = 0, \
  parameter     CoefRomFile  = "rtl/core/formal/coef_fv.hex", \
  parameter     CosRomFile   = "rtl/core/formal/cos_k_fv.hex", \
  parameter int TagBits      = 2

// `SPECULAR_FV_START_IN_RESET(clk, rst_n): assume rst_n low in the first cycle, so that
// the base case starts from the reset state (resets may come again at any clock).
`define SPECULAR_FV_START_IN_RESET(clk, rst_n) \
  logic f_started_q = 1'b0;                     \
  always_ff @(posedge (clk)) begin              \
    f_started_q <= 1'b1;                        \
  end                                           \
  always_comb begin                             \
    if (!f_started_q) begin                     \
      assume (!(rst_n));                        \
    end                                         \
  end

// `SPECULAR_FV_AXIS_RULES(name, src, bits, valid, ready, data): the valid/ready rules of
// one port (rtl/prim/formal/specular_axis_props.sv), on the harness's clk_i and rst_ni:
// assumed at a port the harness drives (src 1'b1), asserted at one the design drives.
`define SPECULAR_FV_AXIS_RULES(name, src, bits, valid, ready, data) \
  specular_axis_props #(.Width(bits), .Source(src)) name ( \
    .clk_i   (clk_i), \
    .rst_ni  (rst_ni), \
    .valid_i (valid), \
    .ready_i (ready), \
    .data_i  (data)   \
  )

// `SPECULAR_FV_STREAM_RULES(in_valid, in_ready, in_bits, in_data, out_valid, out_ready,
// out_bits, out_data): a harness's two handshakes. The design starts in reset; the rules are
// assumed at the input the harness drives and asserted at the design's output (P1: valid
// held, data stable while stalled); accept (an input transfer) and xfer (an output transfer)
// are declared for the harness's own properties.
`define SPECULAR_FV_STREAM_RULES(in_valid, in_ready, in_bits, in_data, out_valid, out_ready, out_bits, out_data) \
  logic accept, xfer; \
  assign accept = (in_valid) && (in_ready); \
  assign xfer   = (out_valid) && (out_ready); \
  `SPECULAR_FV_START_IN_RESET(clk_i, rst_ni) \
  `SPECULAR_FV_AXIS_RULES(u_in_rules, 1'b1, in_bits, in_valid, in_ready, in_data); \
  `SPECULAR_FV_AXIS_RULES(u_out_rules, 1'b0, out_bits, out_valid, out_ready, out_data)

`endif  // SPECULAR_FV_SVH
