// SPDX-License-Identifier: Apache-2.0
//
// specular_streak_props: "once cond_i has held for Max consecutive cycles, ok_i holds",
// written once for the progress properties of the formal harnesses
// (docs/formal.md#the-handshake-rules): sustained rate (spans always offered, ready always
// high: an output every clock) and valid not waiting for ready. count_o, the consecutive
// cycles with cond_i so far (saturating at Max; cleared by a cycle without it and by
// reset), is an output because the harnesses' strengthening invariants relate it to the
// pipeline's fill.
//
// Not in any filelist (rtl/README.md#filelists): scripts/formal.sh reads it beside the
// harness.

module specular_streak_props #(
  parameter int Max   = 1,
  parameter int CBits = $clog2(Max + 1)
) (
  input  logic             clk_i,
  input  logic             rst_ni,
  input  logic             cond_i,
  input  logic             ok_i,
  output logic [CBits-1:0] count_o
);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      count_o <= '0;
    end else if (cond_i) begin
      if (count_o != CBits'(Max)) begin
        count_o <= count_o + 1'b1;
      end
    end else begin
      count_o <= '0;
    end
  end

`ifdef FORMAL
  always_comb begin
    if (rst_ni && count_o == CBits'(Max)) begin
      assert (ok_i);
    end
  end
`else
  logic unused;
  assign unused = ok_i;
`endif

endmodule
