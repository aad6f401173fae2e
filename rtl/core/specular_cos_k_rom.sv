// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// cos^k ROM, block 12 of patent UA 71489 (the "first ROM"): NumBanks banks of
// 2^CosAddrBits words, one bank per k of the bank set; the decoder's one-hot select
// (block 10) picks the bank through the top address bits. h = pi/2 / 2^CosAddrBits.
//
// CosInterp = 1 (the default build): linear interpolation between entries. Word
// bank * 2^CosAddrBits + i is {v, d}: v = round(cos^k(i h) * 2^CosDataBits) in
// CosDataBits + 1 bits (cos^k(0) = 1 is exact), d = v - v(i + 1) in CosDeltaBits bits
// (v(2^CosAddrBits) = 0). With frac_i = t (the CosFracBits of zeta below the address):
//   cosk = v - ((d * t + 2^(CosFracBits-1)) >> CosFracBits)
// The interpolated cos has a bounded relative error even next to its zero at pi/2, which a
// direct table does not (n = 1); 256 entries per bank reach ten times the accuracy of the
// patent's 4096 in a sixteenth of the words.
// CosInterp = 0 (the patent's direct table): word = min(round(cos^k(i h) * 2^CosDataBits),
// 2^CosDataBits - 1), cosk = word (cos^k(0) = 1 saturates deliberately).
//
// Erratum (docs/device.md#errata-of-the-patent-and-how-each-is-resolved): only [0, pi/2) is stored; multiplier 11 feeds |zeta| (cos is even)
// and flags zeta >= pi/2 as zero, so no address outside a bank is ever needed.
//
// Contents: $readmemh(CosRomFile) in specular_rom, words 0 .. Depth - 1: one hex word per
// line, no comments, no @ addresses, bank 0 first (roms/README.md). The testbenches check the file's length
// against the parameters before elaborating (a short file would load silently here).
// Synchronous read with read enable (block RAM, RE of SB_RAM40_4K), no reset.
//
// Reads = 2 (the blend, docs/display_exact.md): a second read of the same words (bank, address
// and weight of read r in field r of each port, read 0 in the low bits), its own
// interpolation; specular_rom's second port (a dual-port block RAM on the ECP5, a copy on the
// iCE40).
//
// Pipeline, every register enabled by en_i: the ROM read (with 3t beside it), then
// (interpolated) the radix-4 t * d tree (specular_pipe_mul) and the subtraction; the direct
// table is delayed by as many clocks, so both take specular_pkg::cos_k_rom_stages clocks
// (docs/pipeline.md#stage-counts).

`include "specular_assert.svh"

module specular_cos_k_rom #(
  parameter int NumBanks     = 8,
  parameter int CosAddrBits  = 8,
  parameter int CosDataBits  = 18,
  parameter bit CosInterp    = 1'b1,
  parameter int CosDeltaBits = 12,
  parameter int CosFracBits  = 12,
  parameter     CosRomFile   = "roms/cos_k_1_2_3_4_6_8_12_16_interp256.hex",
  parameter int MulTileBits  = 0,  // specular_pipe_mul's TileBits: 0 LUT tree, 16 / 18 DSP tiles
  parameter int Reads        = 1   // reads per pixel: 1, or 2 for the blend
) (
  input  logic                           clk_i,
  input  logic                           en_i,    // pipeline advance: holds every stage while stalled
  input  logic [Reads*NumBanks-1:0]      bank_i,  // one-hot from decoder 10 (all zero: bank 0)
  input  logic [Reads*CosAddrBits-1:0]   addr_i,  // entry within the bank
  input  logic [Reads*CosFracBits-1:0]   frac_i,  // interpolation weight t
  output logic [Reads*(CosDataBits+1)-1:0] cosk_o // cos^k, CosDataBits fraction bits (1.0 possible)
);

  localparam int BankBits  = (NumBanks > 1) ? $clog2(NumBanks) : 1;
  localparam int Depth     = NumBanks << CosAddrBits;
  localparam int WordBits  = CosInterp ? CosDataBits + 1 + CosDeltaBits : CosDataBits;
  localparam int MulStages = specular_pkg::pipe_mul_stages(CosDeltaBits);
  localparam int AddrBits  = (NumBanks > 1) ? BankBits + CosAddrBits : CosAddrBits;

  if (specular_pkg::Rom12ReadStages != 1 || specular_pkg::Rom12OutStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_cos_k_rom: builds one read register and one subtraction register (specular_pkg)")
  end
  if (CosInterp && CosDeltaBits > CosDataBits) begin : gen_delta_check
    `SPEC_PARAM_ERROR("specular_cos_k_rom: CosDeltaBits must not exceed CosDataBits")
  end
  if (Reads < 1 || Reads > 2) begin : gen_reads_check
    `SPEC_PARAM_ERROR("specular_cos_k_rom: Reads must be 1 or 2")
  end

  logic [Reads*AddrBits-1:0] addr;
  logic [Reads*WordBits-1:0] words_q;

  specular_rom #(
    .Width    (WordBits),
    .AddrBits (AddrBits),
    .Depth    (Depth),
    .File     (CosRomFile),
    .Reads    (Reads)
  ) u_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (addr),
    .data_o (words_q)
  );

  for (genvar r = 0; r < Reads; r++) begin : gen_read
    logic [NumBanks-1:0]    bank;
    logic [BankBits-1:0]    bank_idx;
    logic [WordBits-1:0]    word_q;
    logic [CosFracBits-1:0] frac_q;
    logic [CosFracBits+1:0] frac3_q;   // 3 t, beside the block RAM read
    assign bank = bank_i[r*NumBanks +: NumBanks];

    always_comb begin
      bank_idx = '0;
      for (int j = 0; j < NumBanks; j++) begin
        if (bank[j]) begin
          bank_idx = bank_idx | BankBits'(j);
        end
      end
    end

    if (NumBanks > 1) begin : gen_multi_bank
      assign addr[r*AddrBits +: AddrBits] = {bank_idx, addr_i[r*CosAddrBits +: CosAddrBits]};
    end else begin : gen_single_bank
      logic unused_bank_idx;
      assign unused_bank_idx = bank_idx[0];
      assign addr[r*AddrBits +: AddrBits] = addr_i[r*CosAddrBits +: CosAddrBits];
    end
    assign word_q = words_q[r*WordBits +: WordBits];

    always_ff @(posedge clk_i) begin
      if (en_i) begin
        frac_q  <= frac_i[r*CosFracBits +: CosFracBits];
        frac3_q <= (CosFracBits + 2)'(frac_i[r*CosFracBits +: CosFracBits])
                   + ((CosFracBits + 2)'(frac_i[r*CosFracBits +: CosFracBits]) << 1);
      end
    end

    if (CosInterp) begin : gen_interp
      logic [CosDataBits:0]                v, v_m;
      logic [CosDeltaBits-1:0]             d;
      logic [CosDeltaBits+CosFracBits-1:0] dt;
      logic [CosDataBits:0]                cosk_q;
      assign v = word_q[WordBits-1 -: CosDataBits + 1];
      assign d = word_q[CosDeltaBits-1:0];

      specular_pipe_mul #(
        .ABits    (CosFracBits),
        .BBits    (CosDeltaBits),
        .TileBits (MulTileBits)
      ) u_step (
        .clk_i (clk_i),
        .en_i  (en_i),
        .a_i   (frac_q),
        .a3_i  (frac3_q),
        .b_i   (d),
        .p_o   (dt)
      );

      specular_delay #(.Width (CosDataBits + 1), .Depth (MulStages), .Reset (1'b0)) u_v (
        .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (v), .q_o (v_m));

      logic [CosDeltaBits+CosFracBits:0] dt_rnd;
      assign dt_rnd = {1'b0, dt} + (CosDeltaBits + CosFracBits + 1)'(1 << (CosFracBits - 1));

      always_ff @(posedge clk_i) begin
        if (en_i) begin
          cosk_q <= v_m - (CosDataBits + 1)'(dt_rnd[CosDeltaBits+CosFracBits:CosFracBits]);
        end
      end
      assign cosk_o[r*(CosDataBits+1) +: CosDataBits + 1] = cosk_q;

      logic unused_dt_lsbs;
      assign unused_dt_lsbs = ^dt_rnd[CosFracBits-1:0];
`ifndef SYNTHESIS
      `SPEC_PRIMED(primed_q, clk_i, en_i)
      logic word_known;
      assign word_known = `SPEC_KNOWN(word_q);
      `SPEC_ASSERT_IF(WordInRange_A, en_i && word_known, v <= (CosDataBits + 1)'(1 << CosDataBits), clk_i, primed_q)
      `SPEC_ASSERT_IF(StepBelowValue_A, en_i && word_known, (CosDataBits + 1)'(d) <= v, clk_i, primed_q)
`endif
    end else begin : gen_direct
      logic [CosDataBits-1:0] w_m;
      specular_delay #(.Width (CosDataBits), .Depth (MulStages + 1), .Reset (1'b0)) u_w (
        .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (word_q), .q_o (w_m));
      assign cosk_o[r*(CosDataBits+1) +: CosDataBits + 1] = {1'b0, w_m};
      logic unused_frac;
      assign unused_frac = ^{frac_q, frac3_q};
    end

    `SPEC_ASSERT_KNOWN_IF(BankKnown_A, bank, en_i, clk_i, 1'b1)
    `SPEC_ASSERT_IF(BankOneHot0_A, en_i, $onehot0(bank), clk_i, 1'b1)
  end

endmodule
