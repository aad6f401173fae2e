// SPDX-License-Identifier: Apache-2.0
//
// specular_px_ghost: the ghost registers of a pixel pipeline, written once for the formal
// harnesses of specular_stream and phong_stream (docs/formal.md#the-handshake-rules). Per
// stage j, g_seq_o and g_idx_o hold the number of the span (or FIFO slot) of stage j's pixel
// and its pixel index; for an empty stage, those of the next pixel to come below the pixels
// above it. They shift with the pipeline (adv_i, the stages' enable), stage 0 taking n_seq_o
// and n_idx_o of stage 0 (the pixel after it), so that each invariant relates two
// neighbouring stages and the induction needs no sum over the whole pipeline. The
// neighbour invariants asserted here hold for every such pipeline: a last flag only on a
// valid stage, no hole inside a span, and each stage's ghosts the successor of the stage
// below it.
//
// Not in any filelist (rtl/README.md#filelists): scripts/formal.sh reads it beside the
// harness.

module specular_px_ghost #(
  parameter int Depth   = 2,  // stages 0 .. Depth - 1
  parameter int SeqBits = 2,  // span number (or FIFO slot) of a stage's pixel
  parameter int IdxBits = 2   // pixel index within its span
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  input  logic                       adv_i,     // the stages move on this edge
  input  logic [Depth-1:0]           vld_i,     // stage j holds a pixel
  input  logic [Depth-1:0]           last_i,    // ... its span's last (stage 0: the core's flag)
  output logic [Depth-1:0]           lastf_o,   // stage j holds its span's last pixel
  output logic [Depth*SeqBits-1:0]   g_seq_o,
  output logic [Depth*IdxBits-1:0]   g_idx_o,
  output logic [Depth*SeqBits-1:0]   n_seq_o,   // of the pixel after stage j's
  output logic [Depth*IdxBits-1:0]   n_idx_o
);

  assign lastf_o = last_i & vld_i;
  for (genvar j = 0; j < Depth; j++) begin : gen_next
    assign n_seq_o[j*SeqBits +: SeqBits] = g_seq_o[j*SeqBits +: SeqBits] + SeqBits'(lastf_o[j]);
    assign n_idx_o[j*IdxBits +: IdxBits] =
        !vld_i[j]  ? g_idx_o[j*IdxBits +: IdxBits] :
        lastf_o[j] ? '0 : g_idx_o[j*IdxBits +: IdxBits] + 1'b1;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      g_seq_o <= '0;
      g_idx_o <= '0;
    end else if (adv_i) begin
      g_seq_o <= {g_seq_o[(Depth-1)*SeqBits-1:0], n_seq_o[SeqBits-1:0]};
      g_idx_o <= {g_idx_o[(Depth-1)*IdxBits-1:0], n_idx_o[IdxBits-1:0]};
    end
  end

`ifdef FORMAL
  for (genvar j = 1; j < Depth; j++) begin : gen_stage
    always_comb begin
      if (rst_ni) begin
        assert (!last_i[j] || vld_i[j]);
        assert (!vld_i[j] || last_i[j] || vld_i[j-1]);
        assert (g_seq_o[(j-1)*SeqBits +: SeqBits] == n_seq_o[j*SeqBits +: SeqBits]);
        assert (g_idx_o[(j-1)*IdxBits +: IdxBits] == n_idx_o[j*IdxBits +: IdxBits]);
      end
    end
  end
`endif

endmodule
