// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Coefficient ROM, block 9 of patent UA 71489 (the "second ROM"): 2^NBits words addressed
// by n (register 4). Word n holds round(a(n, k(n)) * 2/pi * 2^CoefFrac), unsigned,
// CoefBits bits, where k(n) is the decoder's bank for n and a the coefficient of the
// chosen policy (maclaurin sqrt(n/k), minimax, kutlog:Q). Scaling by 2/pi makes the
// product of multiplier 11 come out in quarter turns. Words 0 and n > 1000 are 0.
//
// Contents: $readmemh(CoefRomFile): one hex word per line, no comments, no @ addresses,
// word 0 first (format documented in roms/README.md). Synchronous read with read enable
// (registered output, no reset; specular_rom) so synthesis maps it to block RAM. The
// stream reads it with the span's n in the cycle the span is accepted, so the word sits
// beside register 4 while the span's pixels leave register 8.

`include "specular_assert.svh"

module specular_coef_rom #(
  parameter int NBits       = 10,
  parameter int CoefBits    = 21,
  parameter     CoefRomFile = "roms/coef_minimax.hex"
) (
  input  logic                clk_i,
  input  logic                en_i,    // read enable: a span is accepted
  input  logic [NBits-1:0]    n_i,
  output logic [CoefBits-1:0] coef_o
);

  specular_rom #(
    .Width    (CoefBits),
    .AddrBits (NBits),
    .File     (CoefRomFile)
  ) u_rom (
    .clk_i  (clk_i),
    .en_i   (en_i),
    .addr_i (n_i),
    .data_o (coef_o)
  );

  // Assertions (rtl/prim/specular_assert.svh; no reset here: an X strobe is vacuous): a read
  // has a known address.
  `SPEC_ASSERT_KNOWN_IF(AddrKnown_A, n_i, en_i, clk_i, 1'b1)

endmodule
