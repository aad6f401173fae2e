// SPDX-License-Identifier: Apache-2.0
//
// specular_axis_props: the valid/ready rules of one AXI4-Stream (or AXI4-Lite channel)
// port, written once for every formal harness (docs/formal.md#the-handshake-rules). A
// harness instantiates it at each port with the port's valid, ready and payload:
//
//   After a cycle with valid_i && !ready_i (and rst_ni high in both), valid_i is still
//   high and data_i is unchanged: valid does not wait for ready and is not withdrawn,
//   the payload is stable until the transfer. A reset releases the port.
//
// Source = 1: the harness drives the port (the design's input): the rules are assumed,
// the environment of the proof. Source = 0: the design drives it (its output): the rules
// are asserted, a property. Unknown values do not arise in the solver's two-valued model;
// in simulation the RTL's own SPEC_ASSERT_KNOWN checks cover them
// (rtl/README.md#assertions-specular_assertsvh).
//
// Not in any filelist (rtl/README.md#filelists): the formal scripts read it beside the
// harness (scripts/formal.sh).

module specular_axis_props #(
  parameter int Width  = 1,
  parameter bit Source = 1'b0
) (
  input logic             clk_i,
  input logic             rst_ni,
  input logic             valid_i,
  input logic             ready_i,
  input logic [Width-1:0] data_i
);

`ifdef FORMAL
  logic             stall_q;  // the last cycle had valid_i && !ready_i
  logic [Width-1:0] held_q;   // the payload of the last cycle
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      stall_q <= 1'b0;
      held_q  <= '0;
    end else begin
      stall_q <= valid_i && !ready_i;
      held_q  <= data_i;
    end
  end

  if (Source) begin : gen_assume
    always_comb begin
      if (rst_ni && stall_q) begin
        assume (valid_i);
        assume (data_i == held_q);
      end
    end
  end else begin : gen_assert
    always_comb begin
      if (rst_ni && stall_q) begin
        assert (valid_i);
        assert (data_i == held_q);
      end
    end
  end
`else
  logic unused;
  assign unused = ^{clk_i, rst_ni, valid_i, ready_i, data_i};
`endif

endmodule
