// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_rom: the read-only memory under ROM 9 (specular_coef_rom) and ROM 12
// (specular_cos_k_rom). Depth words of Width bits, loaded with $readmemh(File) at
// elaboration (one hex word per line, no comments, no @ addresses, word 0 first;
// roms/README.md). Synchronous read with read enable, registered output, no reset, so that
// synthesis maps it to block RAM; data_o is the word addressed at the last enabled edge.
// Reads = 2 gives a second read port on the same words (addr_i and data_o hold one field per
// port, port 0 in the low bits): one dual-port block RAM on the ECP5 (DP16KD), two copies on
// the iCE40, whose block RAM has one read port.
// In simulation a word the file left X (a four-state simulator sees it: the file is too
// short) fails AllWordsLoaded_A at time 0, and an instance with no File fails FileGiven_A.

`include "specular_assert.svh"

module specular_rom #(
  parameter int Width    = 1,
  parameter int AddrBits = 1,
  parameter int Depth    = 1 << AddrBits,  // words 0 .. Depth - 1 exist
  parameter     File     = "",
  parameter int Reads    = 1                 // read ports: 1 or 2
) (
  input  logic                      clk_i,
  input  logic                      en_i,    // read enable (every port)
  input  logic [Reads*AddrBits-1:0] addr_i,  // < Depth
  output logic [Reads*Width-1:0]    data_o
);

  if (Width < 1 || AddrBits < 1 || Depth < 1 || Depth > (1 << AddrBits)) begin : gen_param_check
    `SPEC_PARAM_ERROR("specular_rom: Width, AddrBits >= 1 and 1 <= Depth <= 2^AddrBits")
  end
  if (Reads < 1 || Reads > 2) begin : gen_reads_check
    `SPEC_PARAM_ERROR("specular_rom: Reads must be 1 or 2")
  end

  logic [Width-1:0] mem [Depth];

  if (File == "") begin : gen_no_file
    // Yosys elaborates a module with its defaults when it reads it (without -defer), so
    // the default must elaborate; a ROM instance without a file fails in simulation.
`ifndef SYNTHESIS
    initial begin
      `SPEC_ASSERT_I(FileGiven_A, 1'b0)
    end
`endif
  end else begin : gen_load
`ifndef SYNTHESIS
    int unsigned unloaded;   // words the file left X
`endif
    initial begin
      $readmemh(File, mem, 0, Depth - 1);
`ifndef SYNTHESIS
      unloaded = 0;
      for (int i = 0; i < Depth; i++) begin
        unloaded += `SPEC_KNOWN(mem[i]) ? 0 : 1;
      end
      `SPEC_ASSERT_I(AllWordsLoaded_A, unloaded == 0)
`endif
    end
  end

  for (genvar r = 0; r < Reads; r++) begin : gen_read
    logic [AddrBits-1:0] addr;
    logic [Width-1:0]    data_q;
    assign addr = addr_i[r*AddrBits +: AddrBits];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        data_q <= mem[addr];
      end
    end
    assign data_o[r*Width +: Width] = data_q;
  end

endmodule
