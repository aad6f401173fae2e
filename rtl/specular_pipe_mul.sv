// Copyright (c) the specular_device authors.
//
// Pipelined unsigned multiplier p = a * b, exact, for the LUT fabric of an iCE40 (no DSP
// needed): the BBits partial products (a << j where b[j] is set) are summed by a binary
// tree of adders with a register after every level, so each clock holds at most one carry
// chain. Latency = Stages = max(1, clog2(BBits)) clocks; a new operand pair every clock.
// en_i freezes every stage (pipeline stall). No reset: the datapath carries no control
// state, the valid bits beside it are reset.
// Used by multiplier 11 (coef * |psi|), the ROM 12 interpolation (d * t) and
// multiplier 13 (C * cos^k) of patent UA 71489.

module specular_pipe_mul #(
  parameter int ABits = 16,
  parameter int BBits = 16
) (
  input  logic                   clk_i,
  input  logic                   en_i,
  input  logic [ABits-1:0]       a_i,
  input  logic [BBits-1:0]       b_i,
  output logic [ABits+BBits-1:0] p_o
);

  localparam int PBits  = ABits + BBits;
  localparam int Stages = (BBits > 1) ? $clog2(BBits) : 1;

  if (ABits < 1 || BBits < 1) begin : gen_width_check
    $error("specular_pipe_mul: widths must be >= 1");
  end

  // rows[l][j]: row j after level l (level 0: the partial products, combinational).
  // Level l has ceil(BBits / 2^l) rows.
  logic [PBits-1:0] rows [Stages+1][BBits];

  for (genvar j = 0; j < BBits; j++) begin : gen_pp
    assign rows[0][j] = b_i[j] ? (PBits'(a_i) << j) : '0;
  end

  for (genvar l = 1; l <= Stages; l++) begin : gen_level
    localparam int NPrev = (BBits + (1 << (l - 1)) - 1) >> (l - 1);
    localparam int NCur  = (BBits + (1 << l) - 1) >> l;
    for (genvar j = 0; j < NCur; j++) begin : gen_row
      logic [PBits-1:0] sum;
      if (2 * j + 1 < NPrev) begin : gen_add
        assign sum = rows[l-1][2*j] + rows[l-1][2*j+1];
      end else begin : gen_pass
        assign sum = rows[l-1][2*j];
      end
      always_ff @(posedge clk_i) begin
        if (en_i) begin
          rows[l][j] <= sum;
        end
      end
    end
    // Rows beyond NCur are not used at this level.
    for (genvar j = NCur; j < BBits; j++) begin : gen_unused_row
      assign rows[l][j] = '0;
    end
  end

  assign p_o = rows[Stages][0];

endmodule
