// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_stream_fv: formal property harness of specular_stream's handshakes. Run by
// scripts/formal.sh (ctest rtl_formal_stream): Yosys read_verilog -formal, the model as
// AIGER, ABC: base case from reset (bmc3) plus induction step (scorr), an unbounded proof.
// Everything below the instance is under `ifdef FORMAL; this file lives in rtl/core/formal/ and
// is not in the filelist rtl/specular.f, so the Verilator and synthesis builds do not read it.
//
// REDUCED PARAMETERS. The solver cannot handle the production widths (a 44-bit
// accumulator, 21-bit multiplier trees, an 8 x 256-word ROM, 11-bit span length) in useful
// time, so the core is instantiated with small widths that satisfy every parameter check
// of the RTL (specular_stream, specular_angle_mul, specular_accumulator, specular_decoder):
//   CBits 4, CFrac 3, AngleBits 8, AngleFrac 4, AccBits 12 (>= AngleBits + LenBits + 1),
//   NBits 4, LenBits 3 (spans of 1..8 pixels), CoefBits 4, CoefFrac 2, PsiMulFrac 2 (the
//   smallest the pi/2 test allows), CosInterp 0 (the direct table), CosAddrBits 2,
//   CosDataBits 4, CosDeltaBits 4, CosFracBits 1, NumBanks 2, BankMaxN {15, 1}, TagBits 2,
//   ROMs rtl/core/formal/coef_fv.hex (16 words) and rtl/core/formal/cos_k_fv.hex (2 banks x 4 words).
// The handshake control (specular_control), counter 5, the stage valids, the tag
// pipeline and the output buffer (specular_out_buf) do not depend on the widths except
// through PipeDepth (14 stages here, 21 at the defaults; the same shift-register structure
// at any depth), so the properties carry over; the datapath values are free-running data to these properties
// (the solver picks any span values; bit-exactness is the simulation regression's job).
//
// Properties (asserted whenever rst_ni is high), under two assumptions: the design starts
// in reset (rst_ni low in the first cycle; it may be pulsed again at any later cycle) and
// the span source follows AXI4-Stream (span_valid_i, once high, stays high with all
// span_*_i stable until accepted; a reset releases it):
//   P1 stall     after a cycle with px_valid_o && !px_ready_i, px_valid_o is still high and
//                px_intensity_o, px_last_o, px_tag_o are unchanged
//   P2 owed      owed = sum of (l + 1) over accepted spans - transfers; px_valid_o -> owed != 0
//   P3 order     a FIFO of accepted (l, tag) and the index of the next pixel in the head
//                span: px_valid_o -> FIFO not empty, px_last_o == (index == l of head),
//                px_tag_o == tag of head. The head pops when its pixel l is transferred, so
//                every span gives exactly l + 1 pixels, in order, last on pixel l, its tag.
//   P4 bubble    once span_valid_i and px_ready_i have both been high (rst_ni high) for
//                Latency + 1 (16 here) consecutive cycles, px_valid_o is high; so with spans
//                always offered and ready always high the output carries a pixel every
//                clock, whatever the span lengths (l = 0 included) and across span changes
//                (the extra cycle: a full output buffer needs one pop before adv is high)
//   P5 reset     after a reset px_valid_o stays low until a span has been accepted
//   P6 idle      while px_valid_o is low, px_intensity_o and px_last_o are 0
// Strengthening invariants (needed for induction, proven like the properties) relate the
// harness state to the stage valids, last flags, counter 5, the tag registers and the
// output buffer of the core, read through the probe wires p_* of the probe table of
// target stream in scripts/formal.sh (connect after flatten; Yosys reads no hierarchical
// references).
// The invariants are local: ghost registers shifted with the pipeline carry each stage's
// FIFO slot and pixel index and running counts of valid and last pixels, so every invariant
// relates two neighbouring stages (or a stage before and after one edge) and none is a sum
// or a walk over the whole pipeline: each property's induction step is local, so ABC's
// scorr proves them one by one (docs/formal.md#the-flow).
// With FV_PROPERTIES_ONLY defined (the mutant runs) the invariants and probes are left out.
// Latency (the core's PipeDepth + 1, the output buffer's clock) is a parameter set by
// scripts/formal.sh.

`include "specular_params.svh"
`include "formal/specular_fv.svh"
`include "specular_span_ports.svh"

module specular_stream_fv #(
  `SPECULAR_FV_PARAMS,
  // Cycles from the accept edge to pixel 0 on the output: the core's PipeDepth + 1 (15 with
  // the reduced widths). scripts/formal.sh sets it from the core's tag delay line (depth
  // PipeDepth - 1, so Latency = its length + 2); a wrong value fails on the probe widths.
  parameter int Latency     = 15
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_SPAN_PORTS(input, output, _i, _o),
  `SPECULAR_PX_PORTS
);

  specular_stream #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits     (TagBits)
  ) u_dut (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    `SPECULAR_SPAN_MAP(_i, _o, span_, _i, _o),
    `SPECULAR_PX_PORT_MAP
  );

`ifdef FORMAL
  // Depth: the core's PipeDepth (stage 0 = register 8 .. stage Depth - 1 = the last
  // stage); the output buffer adds one clock (Latency = Depth + 1) and two entries.
  // Spans in flight: at most one per stage or buffer entry (l = 0 spans), Depth + 2 =
  // Latency + 1 in all, so 2^SlotBits >= Latency + 1 FIFO slots never overflow.
  localparam int Depth     = Latency - 1;
  localparam int SlotBits  = $clog2(Latency + 1);
  localparam int Slots     = 1 << SlotBits;
  localparam int IdxBits   = LenBits + 1;            // ghost pixel index, no wrap
  localparam int OweBits   = $clog2((1 << LenBits) + Latency + 1) + 1;  // owed <= 2^l + Latency
  localparam int StreakMax = Latency + 1;            // P4: the buffer's room takes one clock
  localparam int StreakBits = $clog2(StreakMax + 1);
  localparam int SpanBits  = CBits + 2 * AngleBits + NBits + LenBits + TagBits;
  localparam int PixBits   = CBits + 1 + TagBits;

  // ---------------------------------------------------------------------------------
  // Assumptions: start in reset; AXI4-Stream source on the span side. P1: valid held and
  // pixel stable while stalled
  // ---------------------------------------------------------------------------------
  `SPECULAR_FV_STREAM_RULES(span_valid_i, span_ready_o, SpanBits, `SPECULAR_SPAN_DATA(span_, _i),
                            px_valid_o, px_ready_i, PixBits, {px_intensity_o, px_last_o, px_tag_o});

  // ---------------------------------------------------------------------------------
  // P2: pixels owed; P5: nothing out after reset before an accept; P6: an invalid output
  // reads 0
  // ---------------------------------------------------------------------------------
  logic [OweBits-1:0] owed_q;
  logic               seen_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      owed_q <= '0;
      seen_q <= 1'b0;
    end else begin
      owed_q <= owed_q + (accept ? OweBits'(span_len_i) + OweBits'(1) : '0)
                       - (xfer ? OweBits'(1) : '0);
      seen_q <= seen_q | accept;
    end
  end
  always_comb begin
    if (rst_ni && px_valid_o) begin
      assert (owed_q != '0);
      assert (seen_q);
    end
    if (!rst_ni) begin
      assert (!px_valid_o);
    end
    if (rst_ni && !px_valid_o) begin
      assert (px_intensity_o == '0 && !px_last_o);
    end
  end

  // ---------------------------------------------------------------------------------
  // P3: spans in order, l + 1 pixels each, last on pixel l, the span's tag
  // ---------------------------------------------------------------------------------
  // The FIFO's (l, tag) words are memories (no reset: only the q_cnt_q words from
  // q_head_q are ever read as valid; memory_map turns the reads into mux trees).
  logic [LenBits-1:0]       q_len_q [Slots];
  logic [TagBits-1:0]       q_tag_q [Slots];
  logic [SlotBits-1:0]      q_head_q, q_tail;
  logic [SlotBits:0]        q_cnt_q;
  logic [LenBits-1:0]       q_idx_q, head_len;
  logic [TagBits-1:0]       head_tag;
  logic                     pop;

  assign q_tail   = q_head_q + SlotBits'(q_cnt_q);
  assign head_len = q_len_q[q_head_q];
  assign head_tag = q_tag_q[q_head_q];
  assign pop      = xfer && (q_idx_q == head_len);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      q_head_q <= '0;
      q_cnt_q  <= '0;
      q_idx_q  <= '0;
    end else begin
      if (pop) begin
        q_head_q <= q_head_q + 1'b1;
      end
      q_cnt_q <= q_cnt_q + (accept ? 1'b1 : 1'b0) - (pop ? 1'b1 : 1'b0);
      if (xfer) begin
        q_idx_q <= pop ? '0 : q_idx_q + 1'b1;
      end
    end
  end
  always_ff @(posedge clk_i) begin
    if (accept) begin
      q_len_q[q_tail] <= span_len_i;
      q_tag_q[q_tail] <= span_tag_i;
    end
  end
  always_comb begin
    if (rst_ni) begin
      assert (q_cnt_q <= (SlotBits + 1)'(Latency + 1));
      if (px_valid_o) begin
        assert (q_cnt_q != '0);
        assert (px_last_o == (q_idx_q == head_len));
        assert (px_tag_o == head_tag);
      end
    end
  end

  // ---------------------------------------------------------------------------------
  // P4: no bubble with spans always offered and ready always high
  // ---------------------------------------------------------------------------------
  logic [StreakBits-1:0] streak_q;
  specular_streak_props #(.Max(StreakMax), .CBits(StreakBits)) u_rate (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .cond_i  (span_valid_i && px_ready_i),
    .ok_i    (px_valid_o),
    .count_o (streak_q)
  );

`ifndef FV_PROPERTIES_ONLY
  // ---------------------------------------------------------------------------------
  // Strengthening invariants on the core's state (probes connected by scripts/formal.sh).
  // Left out (FV_PROPERTIES_ONLY) by the mutant runs, so that a caught mutant has broken
  // one of P1 .. P6 and not merely an invariant of the intact core.
  // ---------------------------------------------------------------------------------
  logic [Depth-1:0]             p_vld;     // stage j holds a pixel (0: register 8)
  logic [Depth-1:1]             p_last;    // stage j's pixel is its span's last
  logic [LenBits-1:0]           p_cnt;     // counter 5
  logic                         p_zero;    // counter 5's registered "count is 0"
  logic [TagBits-1:0]           p_tag0;    // the tag register (stage 0's span)
  logic [(Depth-1)*TagBits-1:0] p_tagline; // the tag delay line, stages 1 ..
  logic [1:0]                   p_count;   // output buffer: entries
  logic [PixBits-1:0]           p_head;    // ... the entry on the output {intensity, last, tag}
  logic [PixBits-1:0]           p_tail;    // ... the entry behind it (valid when 2 entries)
  logic                         p_adv;     // ... its registered room: the pipeline advance
  logic [Depth*TagBits-1:0]     p_tag;     // tag of stage j's span
  assign p_tag = {p_tagline, p_tag0};

  logic b_head, b_tail, head_last, tail_last;   // buffer entries valid / last
  logic [TagBits-1:0] tail_tag;
  assign b_head    = p_count != 2'd0;
  assign b_tail    = p_count == 2'd2;
  assign head_last = p_head[TagBits];
  assign tail_last = p_tail[TagBits];
  assign tail_tag  = p_tail[TagBits-1:0];

  // The slot and pixel index the buffer's entries and the last stage must have: the head
  // entry's pixel is (q_head_q, q_idx_q); a last flag moves to the next slot.
  logic [SlotBits-1:0] t_slot, s_slot;     // slot of the tail, of stage Depth - 1
  logic [IdxBits-1:0]  t_idx, s_idx, t_len;
  assign t_slot = q_head_q + SlotBits'(b_head && head_last);
  assign t_idx  = !b_head ? IdxBits'(q_idx_q) : head_last ? '0 : IdxBits'(q_idx_q) + 1'b1;
  assign t_len  = IdxBits'(q_len_q[t_slot]);
  assign s_slot = t_slot + SlotBits'(b_tail && tail_last);
  assign s_idx  = !b_tail ? t_idx : tail_last ? '0 : t_idx + 1'b1;

  // Ghosts, shifted with the pipeline (every edge with p_adv high, as the core's stages), so
  // that each invariant below relates two neighbouring stages, or one stage before and after
  // an edge, and the induction needs no sum over the whole pipeline:
  //   g_slot, g_idx  per stage j: the FIFO slot and pixel index of stage j's pixel; for an
  //                  empty stage, those of the next pixel to come below the pixels above it
  //   g_nv, g_nl     per stage j >= 1: valid pixels, and valid last pixels, in stages 1 .. j
  localparam int CntBits = SlotBits + 1;
  logic [Depth-1:0]          lastf;    // stage j holds its span's last pixel
  logic [Depth*SlotBits-1:0] g_slot_q, n_slot;
  logic [Depth*IdxBits-1:0]  g_idx_q, n_idx;
  logic [Depth*CntBits-1:0]  g_nv_q, g_nl_q;   // field 0 unused (0)
  // g_slot, g_idx and n_* (the slot and index of the pixel after stage j's, stage j's own
  // when it is empty), with their neighbour invariants.
  specular_px_ghost #(.Depth(Depth), .SeqBits(SlotBits), .IdxBits(IdxBits)) u_ghost (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .adv_i   (p_adv),
    .vld_i   (p_vld),
    .last_i  ({p_last, p_zero}),
    .lastf_o (lastf),
    .g_seq_o (g_slot_q),
    .g_idx_o (g_idx_q),
    .n_seq_o (n_slot),
    .n_idx_o (n_idx)
  );
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      g_nv_q   <= '0;
      g_nl_q   <= '0;
    end else if (p_adv) begin
      for (int j = 1; j < Depth; j++) begin
        g_nv_q[j*CntBits +: CntBits] <=
            (j == 1 ? '0 : g_nv_q[(j-1)*CntBits +: CntBits]) + CntBits'(p_vld[0]);
        g_nl_q[j*CntBits +: CntBits] <=
            (j == 1 ? '0 : g_nl_q[(j-1)*CntBits +: CntBits]) + CntBits'(lastf[0]);
      end
    end
  end

  logic [SlotBits:0] n_last;   // spans whose last pixel is in the buffer or stages 1 ..
  assign n_last = (SlotBits + 1)'(b_head && head_last) + (SlotBits + 1)'(b_tail && tail_last)
                  + g_nl_q[(Depth-1)*CntBits +: CntBits];
  logic [OweBits-1:0] owed_exp;
  assign owed_exp = OweBits'(p_count) + (p_vld[0] ? OweBits'(p_cnt) + OweBits'(1) : '0)
                    + OweBits'(g_nv_q[(Depth-1)*CntBits +: CntBits]);

  for (genvar j = 0; j < Depth; j++) begin : gen_inv
    logic [SlotBits-1:0] slot;
    logic [IdxBits-1:0]  idx, len;
    assign slot = g_slot_q[j*SlotBits +: SlotBits];
    assign idx  = g_idx_q[j*IdxBits +: IdxBits];
    assign len  = IdxBits'(q_len_q[slot]);
    always_comb begin
      if (rst_ni && p_vld[j]) begin
        assert (p_tag[j*TagBits +: TagBits] == q_tag_q[slot]);
        assert (idx <= len);
        assert (lastf[j] == (idx == len));
      end
    end
    if (j >= 1) begin : gen_stage
      always_comb begin
        if (rst_ni) begin
          assert (g_nv_q[j*CntBits +: CntBits] ==
                  (j == 1 ? '0 : g_nv_q[(j-1)*CntBits +: CntBits]) + CntBits'(p_vld[j]));
          assert (g_nl_q[j*CntBits +: CntBits] ==
                  (j == 1 ? '0 : g_nl_q[(j-1)*CntBits +: CntBits]) + CntBits'(lastf[j]));
        end
      end
    end else begin : gen_reg8
      always_comb begin
        if (rst_ni) begin
          if (p_vld[0]) begin
            assert (IdxBits'(p_cnt) == len - idx);
            assert (slot + 1'b1 == q_tail);
          end else begin
            assert (slot == q_tail && idx == '0);
          end
        end
      end
    end
  end
  always_comb begin
    if (rst_ni) begin
      assert (g_slot_q[(Depth-1)*SlotBits +: SlotBits] == s_slot);
      assert (g_idx_q[(Depth-1)*IdxBits +: IdxBits] == s_idx);
    end
  end

  // Output buffer: at most two entries, its room register, an empty buffer reads 0, the
  // tail entry (its pixel follows the head's) and no gap between the youngest entry and
  // the last stage inside a span.
  always_comb begin
    if (rst_ni) begin
      assert (p_count <= 2'd2);
      assert (p_adv == (p_count <= 2'd1));
      assert (b_head || p_head == '0);
      assert (b_head || q_idx_q == '0);
      assert (!b_head || IdxBits'(q_idx_q) <= IdxBits'(head_len));
      if (b_tail) begin
        assert (tail_tag == q_tag_q[t_slot]);
        assert (t_idx <= t_len);
        assert (tail_last == (t_idx == t_len));
      end
      if (p_count == 2'd1 && !head_last) begin
        assert (p_vld[Depth-1]);
      end
      if (b_tail && !tail_last) begin
        assert (p_vld[Depth-1]);
      end
    end
  end

  // P4's fill: one qualifying cycle gives the buffer room, k + 1 fill stages 0 .. k - 1.
  always_comb begin
    if (rst_ni && streak_q >= StreakBits'(1)) begin
      assert (p_adv);
    end
  end
  for (genvar k = 1; k <= Depth; k++) begin : gen_fill
    always_comb begin
      if (rst_ni && streak_q >= StreakBits'(k + 1)) begin
        assert (&p_vld[k-1:0]);
      end
    end
  end

  always_comb begin
    if (rst_ni) begin
      assert (p_zero == (p_cnt == '0));
      assert (q_cnt_q == n_last + (SlotBits + 1)'(p_vld[0]));
      assert (owed_q == owed_exp);
      assert (seen_q || owed_q == '0);
    end
  end
`endif  // FV_PROPERTIES_ONLY
`endif  // FORMAL

endmodule
