// Copyright (c) the specular_device authors.
//
// Delay line of Depth registers with a common enable (pipeline stall) and no reset, for
// datapath values whose validity travels in reset valid bits elsewhere (block RAM and
// multiplier outputs have no reset either). Depth = 0 is a wire.

module specular_delay_nr #(
  parameter int Width = 1,
  parameter int Depth = 1
) (
  input  logic             clk_i,
  input  logic             en_i,
  input  logic [Width-1:0] d_i,
  output logic [Width-1:0] q_o
);

  if (Width < 1 || Depth < 0) begin : gen_param_check
    $error("specular_delay_nr: Width must be >= 1 and Depth >= 0");
  end

  if (Depth == 0) begin : gen_wire
    logic unused_clk;
    assign unused_clk = clk_i ^ en_i;
    assign q_o = d_i;
  end else begin : gen_regs
    logic [Width-1:0] pipe_q [Depth];
    always_ff @(posedge clk_i) begin
      if (en_i) begin
        pipe_q[0] <= d_i;
        for (int i = 1; i < Depth; i++) begin
          pipe_q[i] <= pipe_q[i-1];
        end
      end
    end
    assign q_o = pipe_q[Depth-1];
  end

endmodule
