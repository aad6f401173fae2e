// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_delay_fv: formal check that specular_delay's ring buffer (Ram = 1, the block-RAM
// style) is its register line clock for clock (docs/formal.md#specular_delay-the-ring-buffer).
// Run by scripts/formal.sh delay (ctest rtl_formal_delay): ABC's pdr, which needs no
// strengthening invariants, on one model holding a pair per depth in Depths (ring and
// register line, the same d_i and en_i, both without reset, every register starting at 0
// as in every formal model here). The depths cover ring sizes of a power of two and not,
// a depth filling its ring (Depth = Words) and the smallest (3). Property, every cycle: the
// two lines' outputs are equal. The formal harnesses of the setup read its lines as
// registers (RamLines = 0); this check carries their proof to the block-RAM lines.
//
// Not in any filelist (rtl/README.md#filelists): scripts/formal.sh reads it.

module specular_delay_fv #(
  parameter int Width = 1,  // the bits of a word do not interact: one stands for all
  parameter int NumDepths = 6,
  parameter logic [NumDepths*8-1:0] Depths = {8'd17, 8'd16, 8'd13, 8'd9, 8'd8, 8'd3}
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [Width-1:0] d_i
);

  for (genvar i = 0; i < NumDepths; i++) begin : gen_pair
    localparam int Depth = Depths[i*8 +: 8];
    logic [Width-1:0] q_ram, q_reg;
    specular_delay #(.Width(Width), .Depth(Depth), .Reset(1'b0), .Ram(1'b1), .RamMinDepth(2),
                     .RamMinBits(1)) u_ram (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (d_i), .q_o (q_ram));
    specular_delay #(.Width(Width), .Depth(Depth), .Reset(1'b0), .Ram(1'b0)) u_reg (
      .clk_i (clk_i), .rst_ni (1'b1), .en_i (en_i), .d_i (d_i), .q_o (q_reg));
`ifdef FORMAL
    always_comb begin
      assert (q_ram == q_reg);
    end
`endif
  end

endmodule
