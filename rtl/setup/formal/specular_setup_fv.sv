// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_fv: formal property harness of specular_setup's handshakes (geometry span
// in, span descriptor out; docs/interfaces.md#geometry-span-interface,
// docs/setup_hw.md#the-rtl). Run by scripts/formal.sh setup (ctests rtl_formal_setup_*):
// the unbounded proof (base case from reset and induction) and two mutants
// (docs/formal.md#specular_setup-the-span-handshakes). Everything below the instance is under
// `ifdef FORMAL; this file is not in the filelist rtl/specular.f.
//
// ABSTRACTION (in scripts/formal.sh setup, documented in docs/formal.md): the script
// cuts the arithmetic datapath where it reaches the descriptor (the wires c_out, psi0_out,
// dpsi_out, a_pos_out, opph_out, oppn_out, n_out, len_out and the status flags become free
// values every clock) and removes the logic left without a reader. What remains is the control: the
// input register's valid, the valid delay line, the tag's delay line, the output buffer.
// No property below constrains a cut value, so the proof covers the real datapath.
// The core keeps its production parameters except TagBits (2 here).
//
// Properties (asserted whenever rst_ni is high), under two assumptions: the design starts in
// reset (resets may come again at any clock) and the producer follows AXI4-Stream
// (geo_valid_i, once high, stays high with every geo_*_i stable until accepted; a reset
// releases it). span_ready_i is free.
//   P1 stall    after a cycle with span_valid_o && !span_ready_i, span_valid_o is still high
//               and every span_*_o is unchanged
//   P2 no wait  once a span has been owed (accepted, not yet transferred) with span_ready_i
//               low for Latency consecutive cycles, span_valid_o is high: valid does not wait
//               for ready
//   P3 owed     span_valid_o -> accepted spans > transferred spans (counted modulo 2^SeqBits;
//               at most Latency + 1 are in flight): no output without an accepted span, and
//               after a reset (counters cleared) nothing from before it comes out
//   P4 order    the solver picks any accepted span (the free input f_pick_i at its accept)
//               and records its tag and its number; when the output's number (transfers so
//               far) equals it, span_tag_o is the recorded tag. With P3: exactly one output
//               per accepted span, in order, with its tag
//   P5 reset    while rst_ni is low, span_valid_o is low
//   P6 rate     once geo_valid_i and span_ready_i have both been high for Latency + 1
//               consecutive cycles, span_valid_o and geo_ready_o are high: one span per clock
//               sustained (the extra cycle: a full output buffer needs one pop before the
//               advance is high)
// Strengthening invariants (needed for induction, proven like the properties) relate ghost
// registers shifted with the pipeline (g_seq: per stage, the number of the stage's span, or
// for an empty stage the number of the next span to come below the ones above it) to the
// core's stage valids, tags and output buffer, read through the probe wires p_* of
// the probe table of its target in scripts/formal.sh (connect after flatten; Yosys reads
// no hierarchical references).
// With FV_PROPERTIES_ONLY defined (the mutant runs) the invariants and probes are left out.

`include "formal/specular_fv.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module specular_setup_fv #(
  parameter int VecBits = 18,
  parameter int TagBits = 2,
  // Registers after the input register (the core's tau of the descriptor, TOUT); set by
  // scripts/formal.sh setup from the length of the valid delay line.
  parameter int Depth   = 99,
  // specular_setup's fixed register formats (the widths of its ports)
  localparam int CBits     = specular_setup_pkg::SpanCBits,
  localparam int AngleBits = specular_setup_pkg::SpanAngleBits,
  localparam int NBits     = specular_setup_pkg::SpanNBits,
  localparam int LenBits   = specular_setup_pkg::SpanLenBits
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_SPAN_PORTS(output, input, _o, _i),
  output logic [2:0]           span_status_o,
  // The solver's choice of the tracked span (P4): high at the accept of the span to track.
  input  logic                 f_pick_i
);

  // SetupII = 1 with its delay lines in registers (RamLines = 0), whose probes read the stage
  // registers; the ring buffers' outputs are the register lines' clock for clock
  // (specular_delay, proven by scripts/formal.sh delay).
  specular_setup #(
    .VecBits  (VecBits),
    .TagBits  (TagBits),
    .RamLines (1'b0)
  ) u_dut (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    `SPECULAR_GEO_PORT_MAP,
    `SPECULAR_SPAN_MAP(_o, _i, span_, _o, _i),
    .span_status_o (span_status_o)
  );

`ifdef FORMAL
  // Latency: from the accept cycle to the cycle the span is on the output (input register,
  // Depth registers, the output buffer). In flight: at most one span per stage (0 .. Depth)
  // plus two buffer entries, Depth + 3 < 2^SeqBits.
  localparam int Latency    = Depth + 2;
  localparam int SeqBits    = $clog2(Depth + 5);
  localparam int StreakMax  = Latency + 1;
  localparam int StreakBits = $clog2(Latency + 2);
  localparam int GeoBits    = `SPECULAR_GEO_DATA_BITS;
  localparam int SpanBits   = CBits + 2 * AngleBits + NBits + LenBits + TagBits + 3;
  // The sideband line's stage (u_dly_side): {len, n, tag, flags}, 2 flags.
  localparam int Flags      = 2;
  localparam int OutW       = LenBits + NBits + TagBits + Flags;

  // ---------------------------------------------------------------------------------
  // Assumptions: start in reset; AXI4-Stream producer on the geometry side. P1: valid held
  // and descriptor stable while stalled; P5: no output in reset
  // ---------------------------------------------------------------------------------
  `SPECULAR_FV_STREAM_RULES(geo_valid_i, geo_ready_o, GeoBits, `SPECULAR_GEO_DATA(geo_, _i),
                            span_valid_o, span_ready_i, SpanBits, {`SPECULAR_SPAN_DATA(span_, _o), span_status_o});
  always_comb begin
    if (!rst_ni) begin
      assert (!span_valid_o);
    end
  end

  // ---------------------------------------------------------------------------------
  // P3: span numbers; P4: the tracked span
  // ---------------------------------------------------------------------------------
  logic [SeqBits-1:0] n_acc_q, n_out_q;   // accepted, transferred (mod 2^SeqBits)
  logic               f_trk_q, f_done_q;
  logic [SeqBits-1:0] f_seq_q;
  logic [TagBits-1:0] f_tag_q;
  logic               f_hit;               // the tracked span is on the output
  assign f_hit = f_trk_q && !f_done_q && span_valid_o && (n_out_q == f_seq_q);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      n_acc_q  <= '0;
      n_out_q  <= '0;
      f_trk_q  <= 1'b0;
      f_done_q <= 1'b0;
      f_seq_q  <= '0;
      f_tag_q  <= '0;
    end else begin
      n_acc_q <= n_acc_q + SeqBits'(accept);
      n_out_q <= n_out_q + SeqBits'(xfer);
      if (accept && f_pick_i && !f_trk_q) begin
        f_trk_q <= 1'b1;
        f_seq_q <= n_acc_q;
        f_tag_q <= geo_tag_i;
      end
      if (f_hit && span_ready_i) begin
        f_done_q <= 1'b1;
      end
    end
  end
  always_comb begin
    if (rst_ni && span_valid_o) begin
      assert (n_acc_q != n_out_q);
    end
    if (rst_ni && f_hit) begin
      assert (span_tag_o == f_tag_q);
    end
  end

  // ---------------------------------------------------------------------------------
  // P2: valid does not wait for ready
  // ---------------------------------------------------------------------------------
  logic [StreakBits-1:0] lo_q;
  specular_streak_props #(.Max(Latency), .CBits(StreakBits)) u_no_wait (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .cond_i  (!span_ready_i && n_acc_q != n_out_q),
    .ok_i    (span_valid_o),
    .count_o (lo_q)
  );

  // ---------------------------------------------------------------------------------
  // P6: one span per clock
  // ---------------------------------------------------------------------------------
  logic [StreakBits-1:0] streak_q;
  specular_streak_props #(.Max(StreakMax), .CBits(StreakBits)) u_rate (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .cond_i  (geo_valid_i && span_ready_i),
    .ok_i    (span_valid_o && geo_ready_o),
    .count_o (streak_q)
  );

`ifndef FV_PROPERTIES_ONLY
  // ---------------------------------------------------------------------------------
  // Strengthening invariants on the core's state (probes connected by
  // scripts/formal.sh setup). Left out (FV_PROPERTIES_ONLY) by the mutant runs.
  // ---------------------------------------------------------------------------------
  logic                    p_vld0;    // the input register holds a span (stage 0)
  logic [TagBits-1:0]      p_tag0;    // ... its tag
  logic [Depth-1:0]        p_vline;   // stage j (1 .. Depth) valid: bit j - 1
  logic [Depth*OutW-1:0]   p_oline;   // stage j's {len, n, tag, flags}: field j - 1
  logic [1:0]              p_count;   // output buffer: entries
  logic [SpanBits-1:0]     p_head;    // ... the entry on the output
  logic [SpanBits-1:0]     p_tail;    // ... the entry behind it
  logic                    p_adv;     // ... its registered room: the pipeline advance

  logic [Depth:0]             vld;
  logic [(Depth+1)*TagBits-1:0] tag;
  assign vld = {p_vline, p_vld0};
  assign tag[TagBits-1:0] = p_tag0;
  for (genvar j = 1; j <= Depth; j++) begin : gen_tag
    assign tag[j*TagBits +: TagBits] = p_oline[(j-1)*OutW + Flags +: TagBits];
  end
  logic [TagBits-1:0] head_tag, tail_tag;
  assign head_tag = p_head[3 +: TagBits];
  assign tail_tag = p_tail[3 +: TagBits];

  // Ghost span numbers, shifted at every edge where the core's stages move (p_adv high).
  logic [(Depth+1)*SeqBits-1:0] g_seq_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      g_seq_q <= '0;
    end else if (p_adv) begin
      g_seq_q <= {g_seq_q[Depth*SeqBits-1:0], n_acc_q};
    end
  end

  logic f_live;  // a tracked span not yet transferred
  assign f_live = f_trk_q && !f_done_q;

  for (genvar j = 0; j <= Depth; j++) begin : gen_inv
    logic [SeqBits-1:0] seq, ahead;
    assign seq   = g_seq_q[j*SeqBits +: SeqBits];
    assign ahead = seq - n_out_q;   // spans in the buffer and stages j + 1 .. Depth
    always_comb begin
      if (rst_ni) begin
        assert (ahead <= SeqBits'(Depth - j + 2));
        assert (ahead >= SeqBits'(p_count));
        if (j < Depth) begin
          assert (seq == g_seq_q[(j+1)*SeqBits +: SeqBits] + SeqBits'(vld[j+1]));
        end else begin
          assert (seq == n_out_q + SeqBits'(p_count));
        end
        if (f_live && vld[j] && seq == f_seq_q) begin
          assert (tag[j*TagBits +: TagBits] == f_tag_q);
        end
        // P2's induction: Latency - j - 1 cycles owed and not ready put the oldest span in
        // stage j + 1 .. Depth or the buffer.
        if (lo_q >= StreakBits'(j + 2)) begin
          assert (p_count != '0 || seq != n_out_q);
        end
        // P6's fill: j + 2 qualifying cycles fill stages 0 .. j.
        if (streak_q >= StreakBits'(j + 2)) begin
          assert (vld[j]);
        end
      end
    end
  end

  always_comb begin
    if (rst_ni) begin
      assert (p_count <= 2'd2);
      assert (p_adv == (p_count <= 2'd1));
      assert (n_acc_q == g_seq_q[SeqBits-1:0] + SeqBits'(p_vld0));
      if (f_live) begin
        assert (SeqBits'(f_seq_q - n_out_q) < SeqBits'(n_acc_q - n_out_q));
      end
      if (f_live && p_count != '0 && n_out_q == f_seq_q) begin
        assert (head_tag == f_tag_q);
      end
      if (f_live && p_count == 2'd2 && n_out_q + 1'b1 == f_seq_q) begin
        assert (tail_tag == f_tag_q);
      end
      if (lo_q >= StreakBits'(1)) begin
        assert (p_count != '0 || n_acc_q != n_out_q);
      end
      if (streak_q >= StreakBits'(1)) begin
        assert (p_adv);
      end
    end
  end
`endif  // FV_PROPERTIES_ONLY
`endif  // FORMAL

endmodule
