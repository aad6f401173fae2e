// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// phong_stream_fv: formal property harness of phong_stream's handshakes (geometry span in,
// pixels out; docs/interfaces.md#geometry-span-interface, docs/phong_hw.md). Run by
// scripts/formal.sh phong: the unbounded proof (base case from reset and induction), or a
// bounded model check from reset (docs/formal.md#phong_stream-the-span-and-pixel-handshakes).
// Everything below the instance is under `ifdef FORMAL; this file is not in the filelist
// rtl/specular.f.
//
// REDUCED PARAMETERS. The core's pipeline depth follows from its widths (phong_pkg): 98
// stages for n1000, 79 for n64, behind a 9-stage span pipe. The harness instantiates it with
// the smallest widths that pass every parameter check of the RTL (below; ROM files left
// empty: the datapath is cut), which gives PipeDepth 40 and a 5-stage span pipe; the
// control (specular_control, specular_down_counter, the tag line, specular_out_buf, the
// span pipe's valid line and its len and tag registers) is the same shift structure at any
// depth. LenBits 3 (spans of 1..8 pixels), TagBits 2.
//
// ABSTRACTION (scripts/formal.sh phong, docs/formal.md#phong_stream-the-span-and-pixel-handshakes):
// the script cuts the pixel value where it leaves the power unit (cutpoint u_dut.intensity:
// a free value every clock) and removes the logic left without a reader (the span setup's
// multipliers, the accumulators, phong_dot, phong_norm and phong_log2 or phong_cross, phong_exp2, the n/scale line). No
// property below constrains the intensity, so the proof covers the real datapath.
//
// Properties (asserted whenever rst_ni is high; P4 while it is low), under two assumptions:
// the design starts in reset (resets may come again at any clock) and the producer follows
// AXI4-Stream (geo_valid_i, once high, stays high with every geo_*_i stable until accepted;
// a reset releases it). px_ready_i is free. Spans are numbered in accept order (modulo
// 2^SeqBits, more than the spans that fit in flight); n_done counts the transfers with
// px_last_o, o_idx the transfers since the last one.
//   P1 stall    after a cycle with px_valid_o && !px_ready_i, px_valid_o is still high and
//               px_intensity_o, px_last_o, px_tag_o are unchanged
//   P2 open     px_valid_o -> accepted spans != n_done: no pixel without an accepted span
//               that is not yet complete (after a reset, none before an accept)
//   P3 order    the solver picks any span number K (the free input f_k_i, constant); the
//               harness records that span's l and tag at its accept. While px_valid_o is
//               high and n_done == K: px_tag_o is the recorded tag, o_idx <= l and
//               px_last_o == (o_idx == l). With P2: every span gives exactly l + 1 pixels,
//               in accept order, with its tag, px_last_o on pixel l and on no other
//   P4 reset    while rst_ni is low, px_valid_o is low
//   P5 idle     while px_valid_o is low, px_intensity_o, px_last_o, px_tag_o are 0
//   P6 ready    px_ready_i high for 2^LenBits + 1 consecutive clocks (rst_ni high) sees
//               geo_ready_o high in one of them: only the pixels of the span in stage 0
//               hold the span side back
// geo_ready_o depending on registers only (never on geo_valid_i or px_ready_i) is checked
// on the netlist by scripts/formal.sh phong (no combinational path into it).
//
// Strengthening invariants (needed for induction, proven like the properties; left out with
// FV_PROPERTIES_ONLY, the bounded and mutant runs) use ghost registers shifted with the
// pipelines, in the style of specular_stream_fv.sv: per span-pipe stage, the span number
// (g_sseq, shifted when the span pipe moves: geo_ready_o); per pixel stage, the span number
// and pixel index (g_seq, g_idx, shifted with the output buffer's advance). Each relates
// neighbouring stages. The probe wires p_* carry the core's state: the probe table of its target in scripts/formal.sh (connect after flatten; Yosys reads
// no hierarchical references).

`include "formal/specular_fv.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module phong_stream_fv #(
  parameter int VecBits       = 2,
  parameter int LenBits       = 3,
  parameter int NBits         = 10,
  parameter int CBits         = 2,
  parameter int TagBits       = 2,
  parameter int OpBits        = 2,
  parameter int NormBits      = 3,
  parameter int RsqrtAddrBits = 3,
  parameter int Newton        = 0,
  parameter int CosFrac       = 3,
  parameter int LogAddrBits   = 1,
  parameter int LogFracBits   = 2,
  parameter int LogBits       = 3,
  parameter int ExpAddrBits   = 1,
  parameter int ExpFracBits   = 2,
  parameter int ExpBits       = 2,
  // Cross = 1 (scripts/formal.sh phong_cross): the cancellation-free form at the smallest widths
  // that pass phong_cross's and phong_span_setup's checks (OpBits 5: no rounding bits).
  parameter bit Cross         = 1'b0,
  // The span pipe's stages (phong_pkg::setup_stages) and the pixel pipeline's (PipeDepth):
  // scripts/formal.sh phong sets them from the widths of u_setup.vld_q and
  // u_control.vld_q; a wrong value fails on the probe widths.
  parameter int SpDepth       = 5,
  parameter int Depth         = 40
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_PX_PORTS,
  // P3: the number of the tracked span (held constant by an assumption).
  input  logic [$clog2(Depth + SpDepth + 3)-1:0] f_k_i
);

  phong_stream #(
    .VecBits       (VecBits),
    .LenBits       (LenBits),
    .NBits         (NBits),
    .CBits         (CBits),
    .TagBits       (TagBits),
    .OpBits        (Cross ? 5 : OpBits),
    .NormBits      (Cross ? 5 : NormBits),
    .Cross         (Cross),
    .UBits         (4),
    .RcpAddrBits   (3),
    .RcpFracBits   (2),
    .RcpBits       (5),
    .SFrac         (8),
    .GAddrBits     (1),
    .GFracBits     (1),
    .GBits         (3),
    .DmFrac        (1),
    .RcpRomFile    (""),
    .GRomFile      (""),
    .RsqrtAddrBits (RsqrtAddrBits),
    .Newton        (Newton),
    .CosFrac       (CosFrac),
    .LogAddrBits   (LogAddrBits),
    .LogFracBits   (LogFracBits),
    .LogBits       (LogBits),
    .ExpAddrBits   (ExpAddrBits),
    .ExpFracBits   (ExpFracBits),
    .ExpBits       (ExpBits),
    .RsqrtRomFile  (""),
    .LogRomFile    (""),
    .ExpRomFile    ("")
  ) u_dut (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    `SPECULAR_GEO_PORT_MAP,
    `SPECULAR_PX_PORT_MAP
  );

`ifdef FORMAL
  // In flight: at most one span per span-pipe stage, per pixel stage (l = 0 spans) and per
  // buffer entry: Depth + SpDepth + 2 < 2^SeqBits.
  localparam int SeqBits   = $clog2(Depth + SpDepth + 3);
  localparam int IdxBits   = LenBits + 1;
  localparam int RBits     = LenBits + 2;
  localparam int GeoBits   = `SPECULAR_GEO_DATA_BITS;
  localparam int PixBits   = CBits + 1 + TagBits;

  logic [PixBits-1:0] px_bus;
  assign px_bus = {px_intensity_o, px_last_o, px_tag_o};

  // ---------------------------------------------------------------------------------
  // Assumptions: start in reset; AXI4-Stream producer; the tracked span's number constant.
  // P1: valid held and pixel stable while stalled
  // ---------------------------------------------------------------------------------
  `SPECULAR_FV_STREAM_RULES(geo_valid_i, geo_ready_o, GeoBits, `SPECULAR_GEO_DATA(geo_, _i),
                            px_valid_o, px_ready_i, PixBits, px_bus);

  logic [SeqBits-1:0] f_k_q;
  always_ff @(posedge clk_i) begin
    f_k_q <= f_k_i;
  end
  always_comb begin
    if (f_started_q) begin
      assume (f_k_i == f_k_q);
    end
  end

  // ---------------------------------------------------------------------------------
  // P4: no pixel in reset; P5: idle reads 0
  // ---------------------------------------------------------------------------------
  always_comb begin
    if (!rst_ni) begin
      assert (!px_valid_o);
    end
    if (rst_ni && !px_valid_o) begin
      assert (px_bus == '0);
    end
  end

  // ---------------------------------------------------------------------------------
  // P2: no pixel without an open span; P3: the tracked span
  // ---------------------------------------------------------------------------------
  logic [SeqBits-1:0] n_acc_q, n_done_q;   // spans accepted, spans completed (mod 2^SeqBits)
  logic [IdxBits-1:0] o_idx_q;             // pixels of span n_done transferred so far
  logic [LenBits-1:0] f_len_q;             // the tracked span's l and tag (last accept of K)
  logic [TagBits-1:0] f_tag_q;
  logic               f_in;                // span K is accepted and not complete
  logic [SeqBits-1:0] acc_ahead;
  assign acc_ahead = n_acc_q - n_done_q;
  assign f_in      = SeqBits'(f_k_q - n_done_q) < acc_ahead;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      n_acc_q  <= '0;
      n_done_q <= '0;
      o_idx_q  <= '0;
    end else begin
      n_acc_q <= n_acc_q + SeqBits'(accept);
      if (xfer) begin
        n_done_q <= n_done_q + SeqBits'(px_last_o);
        o_idx_q  <= px_last_o ? '0 : o_idx_q + 1'b1;
      end
    end
  end
  always_ff @(posedge clk_i) begin
    if (accept && n_acc_q == f_k_q) begin
      f_len_q <= geo_len_i;
      f_tag_q <= geo_tag_i;
    end
  end
  always_comb begin
    if (rst_ni && px_valid_o) begin
      assert (acc_ahead != '0);
      if (n_done_q == f_k_q) begin
        assert (px_tag_o == f_tag_q);
        assert (o_idx_q <= IdxBits'(f_len_q));
        assert (px_last_o == (o_idx_q == IdxBits'(f_len_q)));
      end
    end
  end

  // ---------------------------------------------------------------------------------
  // P6: px_ready_i high does not leave geo_ready_o low for more than 2^LenBits clocks
  // ---------------------------------------------------------------------------------
  logic [RBits-1:0] r_q;   // consecutive clocks with px_ready_i high and geo_ready_o low
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      r_q <= '0;
    end else if (px_ready_i && !geo_ready_o) begin
      if (r_q != RBits'(1 << LenBits) + 1'b1) begin
        r_q <= r_q + 1'b1;
      end
    end else begin
      r_q <= '0;
    end
  end
  always_comb begin
    if (rst_ni) begin
      assert (r_q <= RBits'(1 << LenBits));
    end
  end

`ifndef FV_PROPERTIES_ONLY
  // ---------------------------------------------------------------------------------
  // Strengthening invariants on the core's state (probes connected by
  // scripts/formal.sh phong). Left out (FV_PROPERTIES_ONLY) by the bounded and mutant runs.
  // ---------------------------------------------------------------------------------
  localparam int Hr       = Cross ? 2 : 0;  // the span setup's headroom stages (Cross)
  localparam int MulDepth = SpDepth - 3 - Hr;  // u_setup.u_side: the multiplier stages
  localparam int AccBits  = VecBits + LenBits;
  localparam int SideW    = 9 * AccBits + 6 + 1 + NBits + LenBits + CBits + TagBits;

  logic [SpDepth-1:0]           p_sp_vld;   // span-pipe stage j holds a span
  logic [LenBits-1:0]           p_len1, p_len2, p_lenh;
  logic [TagBits-1:0]           p_tag1, p_tag2, p_tagh;
  logic [LenBits-1:0]           p_lenr1, p_lenr2;  // Cross only: the headroom stages
  logic [TagBits-1:0]           p_tagr1, p_tagr2;
  logic [MulDepth*SideW-1:0]    p_side;     // {.., len, scale, tag} per multiplier stage
  logic [Depth-1:0]             p_vld;      // pixel stage j holds a pixel (0: accumulators)
  logic [Depth-1:1]             p_last;     // ... its span's last
  logic [LenBits-1:0]           p_cnt;      // the pixel counter (stage 0: pixels still to make)
  logic                         p_zero;     // ... its registered zero flag
  logic [TagBits-1:0]           p_tag0;     // stage 0's tag
  logic [(Depth-1)*TagBits-1:0] p_tagline;  // stages 1 .. Depth - 1
  logic [1:0]                   p_count;    // output buffer: entries
  logic [PixBits-1:0]           p_head;     // ... the entry on the output
  logic [PixBits-1:0]           p_tail;     // ... the entry behind it
  logic                         p_adv;      // ... its registered room: the pixel pipe's advance

  // The span pipe's len and tag per stage: 0 and 1 the registers of its stages 1 and 2, (Cross:
  // 2 and 3 the headroom stages',) then the multiplier stages' side line, the head.
  logic [SpDepth*LenBits-1:0] sp_len;
  logic [SpDepth*TagBits-1:0] sp_tag;
  assign sp_len[0 +: LenBits]                 = p_len1;
  assign sp_tag[0 +: TagBits]                 = p_tag1;
  assign sp_len[LenBits +: LenBits]           = p_len2;
  assign sp_tag[TagBits +: TagBits]           = p_tag2;
  assign sp_len[(SpDepth-1)*LenBits +: LenBits] = p_lenh;
  assign sp_tag[(SpDepth-1)*TagBits +: TagBits] = p_tagh;
  if (Cross) begin : gen_hr
    assign sp_len[2*LenBits +: LenBits] = p_lenr1;
    assign sp_tag[2*TagBits +: TagBits] = p_tagr1;
    assign sp_len[3*LenBits +: LenBits] = p_lenr2;
    assign sp_tag[3*TagBits +: TagBits] = p_tagr2;
  end else begin : gen_no_hr
    logic unused_pr;
    assign unused_pr = ^{p_lenr1, p_tagr1, p_lenr2, p_tagr2};
  end
  for (genvar m = 1; m <= MulDepth; m++) begin : gen_side
    assign sp_len[(m+1+Hr)*LenBits +: LenBits] = p_side[(m-1)*SideW + TagBits + CBits +: LenBits];
    assign sp_tag[(m+1+Hr)*TagBits +: TagBits] = p_side[(m-1)*SideW +: TagBits];
  end

  logic [Depth*TagBits-1:0] p_tag;   // pixel stage j's tag
  assign p_tag = {p_tagline, p_tag0};

  logic b_head, b_tail, head_last, tail_last;
  logic [TagBits-1:0] tail_tag;
  logic [1:0]         buf_lasts;     // last pixels in the buffer
  assign b_head    = p_count != 2'd0;
  assign b_tail    = p_count == 2'd2;
  assign head_last = p_head[TagBits];
  assign tail_last = p_tail[TagBits];
  assign tail_tag  = p_tail[TagBits-1:0];
  assign buf_lasts = 2'(b_head && head_last) + 2'(b_tail && tail_last);

  // Span number and pixel index of the buffer's tail entry and of the last stage (the pixel
  // after the buffer's youngest entry); the head entry's are (n_done, o_idx).
  logic [SeqBits-1:0] t_seq, s_seq;
  logic [IdxBits-1:0] t_idx, s_idx;
  assign t_seq = n_done_q + SeqBits'(b_head && head_last);
  assign t_idx = !b_head ? o_idx_q : head_last ? '0 : o_idx_q + 1'b1;
  assign s_seq = t_seq + SeqBits'(b_tail && tail_last);
  assign s_idx = !b_tail ? t_idx : tail_last ? '0 : t_idx + 1'b1;

  // Ghosts. Span pipe: g_sseq, per stage the number of its span, or for an empty stage of
  // the next span to come below the ones above it; shifted when the span pipe moves
  // (geo_ready_o is its enable). Pixel pipe: g_seq, g_idx, per stage the span number and
  // pixel index of its pixel, or for an empty stage of the next pixel to come below the
  // ones above it; shifted at every edge with p_adv high, as the stages.
  logic [SpDepth*SeqBits-1:0] g_sseq_q;
  logic [Depth*SeqBits-1:0]   g_seq_q, n_seq;
  logic [Depth*IdxBits-1:0]   g_idx_q, n_idx;
  logic [Depth-1:0]           lastf;   // pixel stage j holds its span's last pixel
  specular_px_ghost #(.Depth(Depth), .SeqBits(SeqBits), .IdxBits(IdxBits)) u_ghost (
    .clk_i   (clk_i),
    .rst_ni  (rst_ni),
    .adv_i   (p_adv),
    .vld_i   (p_vld),
    .last_i  ({p_last, p_zero}),
    .lastf_o (lastf),
    .g_seq_o (g_seq_q),
    .g_idx_o (g_idx_q),
    .n_seq_o (n_seq),
    .n_idx_o (n_idx)
  );
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      g_sseq_q <= '0;
    end else if (geo_ready_o) begin
      g_sseq_q <= {g_sseq_q[(SpDepth-1)*SeqBits-1:0], n_acc_q};
    end
  end

  // Span pipe: neighbours, bounds (no wrap of the span numbers), the tracked span's l and tag.
  for (genvar j = 0; j < SpDepth; j++) begin : gen_sp_inv
    logic [SeqBits-1:0] seq, ahead;
    assign seq   = g_sseq_q[j*SeqBits +: SeqBits];
    assign ahead = seq - n_done_q;
    always_comb begin
      if (rst_ni) begin
        if (j < SpDepth - 1) begin
          assert (seq == g_sseq_q[(j+1)*SeqBits +: SeqBits] + SeqBits'(p_sp_vld[j+1]));
        end
        assert (ahead >= SeqBits'(buf_lasts));
        assert (ahead <= SeqBits'(Depth + 2 + SpDepth - 1 - j));
        if (p_sp_vld[j]) begin
          assert (ahead < acc_ahead);
        end
        if (p_sp_vld[j] && seq == f_k_q && f_in) begin
          assert (sp_len[j*LenBits +: LenBits] == f_len_q);
          assert (sp_tag[j*TagBits +: TagBits] == f_tag_q);
        end
      end
    end
  end

  // Pixel pipe: neighbours, bounds, the tracked span's pixels (tag, index, last flag).
  for (genvar j = 0; j < Depth; j++) begin : gen_inv
    logic [SeqBits-1:0] seq, ahead;
    logic [IdxBits-1:0] idx;
    assign seq   = g_seq_q[j*SeqBits +: SeqBits];
    assign idx   = g_idx_q[j*IdxBits +: IdxBits];
    assign ahead = seq - n_done_q;
    always_comb begin
      if (rst_ni) begin
        assert (ahead >= SeqBits'(buf_lasts));
        assert (ahead <= SeqBits'(Depth + 1 - j));
        if (p_vld[j]) begin
          assert (ahead < acc_ahead);
        end
        if (p_vld[j] && seq == f_k_q && f_in) begin
          assert (p_tag[j*TagBits +: TagBits] == f_tag_q);
          assert (idx <= IdxBits'(f_len_q));
          assert (lastf[j] == (idx == IdxBits'(f_len_q)));
        end
      end
    end
    if (j == 0) begin : gen_stage0
      // Stage 0 and the span pipe's head: the next span the control takes is the head's.
      logic [SeqBits-1:0] head_seq;
      assign head_seq = g_sseq_q[(SpDepth-1)*SeqBits +: SeqBits];
      always_comb begin
        if (rst_ni) begin
          if (p_vld[0]) begin
            assert (seq + 1'b1 == head_seq);
            if (seq == f_k_q && f_in) begin
              assert (IdxBits'(p_cnt) == IdxBits'(f_len_q) - idx);
            end
          end else begin
            assert (seq == head_seq && idx == '0);
          end
        end
      end
    end
  end

  // Acceptance count, the last stage against the buffer, the buffer itself.
  always_comb begin
    if (rst_ni) begin
      assert (n_acc_q == g_sseq_q[SeqBits-1:0] + SeqBits'(p_sp_vld[0]));
      assert (g_seq_q[(Depth-1)*SeqBits +: SeqBits] == s_seq);
      assert (g_idx_q[(Depth-1)*IdxBits +: IdxBits] == s_idx);
      assert (p_zero == (p_cnt == '0));
      assert (p_count <= 2'd2);
      assert (p_adv == (p_count <= 2'd1));
      assert (b_head || p_head == '0);
      assert (b_head || o_idx_q == '0);
      if (b_tail) begin
        assert (SeqBits'(t_seq - n_done_q) < acc_ahead);
        if (t_seq == f_k_q && f_in) begin
          assert (tail_tag == f_tag_q);
          assert (t_idx <= IdxBits'(f_len_q));
          assert (tail_last == (t_idx == IdxBits'(f_len_q)));
        end
      end
      if (p_count == 2'd1 && !head_last) begin
        assert (p_vld[Depth-1]);
      end
      if (b_tail && !tail_last) begin
        assert (p_vld[Depth-1]);
      end
      // P6: after one clock of px_ready_i the buffer has room; each further clock with
      // geo_ready_o low takes one pixel off the counter.
      if (r_q != '0) begin
        assert (p_adv);
        assert (RBits'(p_cnt) + r_q <= RBits'(1 << LenBits));
      end
    end
  end
`endif  // FV_PROPERTIES_ONLY
`endif  // FORMAL

endmodule
