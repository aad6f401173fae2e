// Copyright (c) the specular_device authors.
//
// cos^k ROM, block 12 of patent UA 71489 (the "first ROM"): NumBanks banks of
// 2^CosAddrBits words, one bank per k of the bank set (default {1, 2, 4, 16}). The
// decoder's one-hot select (block 10) picks the bank through the top address bits.
// Word bank * 2^CosAddrBits + i holds
//   min(round(cos^k(i * pi/2 / 2^CosAddrBits) * 2^CosDataBits), 2^CosDataBits - 1),
// so cos^k(0) = 1 saturates deliberately to the largest code.
//
// Erratum (SPEC 5): the ROM covers only [0, pi/2). Multiplier 11 feeds it |zeta| (cos is
// even) and flags zeta >= pi/2 as zero, so no address outside a bank is ever needed.
//
// Contents: $readmemh(CosRomFile): one hex word per line, no comments, no @ addresses,
// bank 0 first (format documented in roms/README.md). Synchronous read with read enable
// (registered output, no reset) so synthesis maps it to block RAM (RE of SB_RAM40_4K).

module specular_cos_k_rom #(
  parameter int NumBanks    = 4,
  parameter int CosAddrBits = 12,
  parameter int CosDataBits = 16,
  parameter     CosRomFile  = "roms/cos_k_1_2_4_16.hex"
) (
  input  logic                   clk_i,
  input  logic                   en_i,     // read enable: holds the output while stalled
  input  logic [NumBanks-1:0]    bank_i,   // one-hot from decoder 10 (all zero: bank 0)
  input  logic [CosAddrBits-1:0] addr_i,   // |zeta| in units of pi/2 / 2^CosAddrBits
  output logic [CosDataBits-1:0] cosk_o    // cos^k, all fraction bits
);

  localparam int BankBits = (NumBanks > 1) ? $clog2(NumBanks) : 1;
  localparam int Depth    = NumBanks << CosAddrBits;

  // One-hot to binary bank number. With no bank selected (invalid n) bank 0 is read;
  // the pixel is forced to 0 downstream anyway.
  logic [BankBits-1:0] bank_idx;
  always_comb begin
    bank_idx = '0;
    for (int j = 0; j < NumBanks; j++) begin
      if (bank_i[j]) begin
        bank_idx = bank_idx | BankBits'(j);
      end
    end
  end

  localparam int AddrBits = (NumBanks > 1) ? BankBits + CosAddrBits : CosAddrBits;

  logic [CosDataBits-1:0] mem [Depth];
  logic [CosDataBits-1:0] cosk_q;
  logic [AddrBits-1:0]    addr;

  if (NumBanks > 1) begin : gen_multi_bank
    assign addr = {bank_idx, addr_i};
  end else begin : gen_single_bank
    logic unused_bank_idx;
    assign unused_bank_idx = bank_idx[0];
    assign addr = addr_i;
  end

  initial begin
    $readmemh(CosRomFile, mem);
  end

  always_ff @(posedge clk_i) begin
    if (en_i) begin
      cosk_q <= mem[addr];
    end
  end

  assign cosk_o = cosk_q;

endmodule
