// Copyright (c) the specular_device authors.
//
// Decoder, block 10 of patent UA 71489: maps the exponent n (register 4) to a one-hot
// select of the ROM 12 bank whose k approximates cos^n. Bank j serves
//   BankMaxN[j-1] < n <= BankMaxN[j]      (BankMaxN[-1] = 0),
// which with the patent's table gives n = 1 -> k = 1, n = 2 -> k = 2, n = 3..6 -> k = 4,
// n = 7..1000 -> k = 16. n = 0 or n > BankMaxN[NumBanks-1] selects no bank and flags the
// exponent invalid: every pixel of the line is then 0.
//
// Erratum (SPEC 5): n up to 1000 needs 10 bits; the patent's decoder has 9 inputs.
//
// BankMaxN is packed, NBits bits per bank, bank 0 in the least significant bits:
// the default is {10'd1000, 10'd6, 10'd2, 10'd1}. The limits must increase strictly.

module specular_decoder #(
  parameter int                      NBits    = 10,
  parameter int                      NumBanks = 4,
  parameter logic [NumBanks*NBits-1:0] BankMaxN = {10'd1000, 10'd6, 10'd2, 10'd1}
) (
  input  logic [NBits-1:0]    n_i,
  output logic [NumBanks-1:0] bank_o,     // one-hot bank select (all zero if invalid)
  output logic                n_valid_o
);

  if (NumBanks < 1) begin : gen_banks_check
    $error("specular_decoder: NumBanks must be >= 1");
  end
  for (genvar j = 1; j < NumBanks; j++) begin : gen_order_check
    if (BankMaxN[j*NBits +: NBits] <= BankMaxN[(j-1)*NBits +: NBits]) begin : gen_err
      $error("specular_decoder: BankMaxN must increase strictly");
    end
  end

  // Bank j is selected when n is above the previous limit and not above its own.
  for (genvar j = 0; j < NumBanks; j++) begin : gen_bank
    logic above_lo, below_hi;
    if (j == 0) begin : gen_first
      assign above_lo = (n_i != '0);
    end else begin : gen_next
      assign above_lo = (n_i > BankMaxN[(j-1)*NBits +: NBits]);
    end
    assign below_hi  = (n_i <= BankMaxN[j*NBits +: NBits]);
    assign bank_o[j] = above_lo & below_hi;
  end

  assign n_valid_o = |bank_o;

endmodule
