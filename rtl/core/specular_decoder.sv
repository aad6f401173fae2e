// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Decoder, block 10 of patent UA 71489: maps the exponent n (register 4) to a one-hot
// select of the ROM 12 bank whose k approximates cos^n. Bank j serves
//   BankMaxN[j-1] < n <= BankMaxN[j]      (BankMaxN[-1] = 0),
// which with the patent's table gives n = 1 -> k = 1, n = 2 -> k = 2, n = 3..6 -> k = 4,
// n = 7..1000 -> k = 16. n = 0 or n > BankMaxN[NumBanks-1] selects no bank and flags the
// exponent invalid: every pixel of the line is then 0.
//
// Erratum (docs/device.md#errata-of-the-patent-and-how-each-is-resolved): n up to 1000 needs 10 bits; the patent's decoder has 9 inputs.
//
// BankMaxN is packed, NBits bits per bank, bank 0 in the least significant bits:
// the default here is the patent's {10'd1000, 10'd6, 10'd2, 10'd1}. The limits must
// increase strictly.
//
// Registered = 0: combinational. Registered = 1 (the stream): the comparisons of n with
// each limit are registered (enabled by en_i) and the one-hot select is formed from them,
// so the outputs follow n_i one clock later and no clock holds a comparison and the
// select logic behind it (an iCE40-UP5K critical path otherwise).

`include "specular_assert.svh"

module specular_decoder #(
  parameter int                      NBits    = 10,
  parameter int                      NumBanks = 4,
  parameter logic [NumBanks*NBits-1:0] BankMaxN = {10'd1000, 10'd6, 10'd2, 10'd1},
  parameter bit                      Registered = 1'b0
) (
  input  logic                clk_i,      // only with Registered
  input  logic                en_i,       // only with Registered
  input  logic [NBits-1:0]    n_i,
  output logic [NumBanks-1:0] bank_o,     // one-hot bank select (all zero if invalid)
  output logic                n_valid_o
);

  if (NumBanks < 1) begin : gen_banks_check
    `SPEC_PARAM_ERROR("specular_decoder: NumBanks must be >= 1")
  end
  for (genvar j = 1; j < NumBanks; j++) begin : gen_order_check
    if (BankMaxN[j*NBits +: NBits] <= BankMaxN[(j-1)*NBits +: NBits]) begin : gen_err
      `SPEC_PARAM_ERROR("specular_decoder: BankMaxN must increase strictly")
    end
  end

  // le[j]: n <= limit of bank j; nz: n != 0. Bank j is selected when n is above the
  // previous limit (not le[j-1]) and not above its own (le[j]).
  logic [NumBanks-1:0] le_d, le;
  logic                nz_d, nz;
  for (genvar j = 0; j < NumBanks; j++) begin : gen_le
    assign le_d[j] = (n_i <= BankMaxN[j*NBits +: NBits]);
  end
  assign nz_d = (n_i != '0);

  if (Registered) begin : gen_reg
    logic [NumBanks-1:0] le_q;
    logic                nz_q;
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        le_q <= le_d;
        nz_q <= nz_d;
      end
    end
    assign le = le_q;
    assign nz = nz_q;
  end else begin : gen_comb
    logic unused_clk;
    assign unused_clk = clk_i ^ en_i;
    assign le = le_d;
    assign nz = nz_d;
  end

  for (genvar j = 0; j < NumBanks; j++) begin : gen_bank
    if (j == 0) begin : gen_first
      assign bank_o[j] = nz & le[0];
    end else begin : gen_next
      assign bank_o[j] = ~le[j-1] & le[j];
    end
  end

  assign n_valid_o = |bank_o;

  // Assertions (rtl/prim/specular_assert.svh): le is a thermometer code (BankMaxN increases
  // strictly), so at most one bank is selected, and exactly one for every n in
  // 1 .. BankMaxN[NumBanks-1]; the outputs are known. There is no reset here: registered,
  // the checks start after the first enabled edge (before it the comparison registers hold
  // their power-up values, random under Verilator's +verilator+rand+reset+2).
`ifndef SYNTHESIS
  logic primed;
  if (Registered) begin : gen_primed_reg
    `SPEC_PRIMED(primed_q, clk_i, en_i)
    assign primed = primed_q;
  end else begin : gen_primed_comb
    assign primed = 1'b1;
  end
  `SPEC_ASSERT(LeThermometer_A, ((le << 1) & ~le) == '0, clk_i, primed)
  `SPEC_ASSERT(BankOneHot0_A, $onehot0(bank_o), clk_i, primed)
  `SPEC_ASSERT_IF(ValidNOneBank_A, nz && le[NumBanks-1], $onehot(bank_o), clk_i, primed)
  `SPEC_ASSERT_KNOWN(OutKnown_A, {bank_o, n_valid_o}, clk_i, primed)
`endif

endmodule
