// SPDX-License-Identifier: Apache-2.0
//
// specular_axil: an AXI4-Lite slave (32-bit data) in front of the stream core. The CPU
// writes a span descriptor into registers and pushes it into a span FIFO; the FIFO feeds
// specular_axis (specular_stream with AXI4-Stream ports, rtl/axi/specular_axis.sv), whose pixels
// leave on the AXI4-Stream master m_axis_px_*. The register map (offsets, fields, access,
// reset values) and the port table are in docs/interfaces.md; this header is authoritative
// where they differ.
//
// Register map (byte offsets; 32-bit registers; address bits [1:0] are ignored; addresses
// at or above 0x100 when AddrWidth > 8 are unmapped):
//   0x00 ID          RO   0x5350_4543 ("SPEC")
//   0x04 VERSION     RO   [31:16] major, [15:0] minor (1.0)
//   0x08 IRQ_EN      RW   [0] BAD_N, [1] PUSH_FULL: irq_o follows ERR & IRQ_EN
//   0x0C ERR         W1C  sticky: [0] BAD_N (a span with n = 0 or n > the last bank's
//                         BankMaxN field, 1000, was pushed; it is still pushed and gives
//                         len + 1 zero pixels), [1] PUSH_FULL (PUSH while the FIFO was
//                         full; that span was dropped)
//   0x10 STATUS      RO   [7:0] FIFO level, [8] FIFO full, [9] busy (a span in the FIFO or
//                         a pixel owed by the core), [10] irq_o
//   0x14 SPANS       RO   spans pushed into the FIFO, modulo 2^32
//   0x18 PIXELS      RO   pixels transferred on m_axis_px, modulo 2^32
//   0x20 SPAN_C      RW   [CBits-1:0]      C
//   0x24 SPAN_PSI0   RW   [AngleBits-1:0]  psi0
//   0x28 SPAN_DPSI   RW   [AngleBits-1:0]  dpsi
//   0x2C SPAN_N      RW   [NBits-1:0]      n
//   0x30 SPAN_LEN    RW   [LenBits-1:0]    l (the span has l + 1 pixels)
//   0x34 SPAN_TAG    RW   [TagBits-1:0]    tag (m_axis_px_tuser of its pixels)
//   0x38 PUSH        WO   a write with any WSTRB bit set pushes SPAN_* into the FIFO;
//                         reads 0
//   0x40 BUILD_CORE  RO   [7:0] Latency (span accepted by the core to pixel 0, clocks),
//                         [15:8] FifoDepth, [23:16] TagBits, [24] CosInterp
//   0x44 BUILD_ROM   RO   [7:0] NumBanks, [15:8] CosAddrBits (ROM 12 entries per bank =
//                         2^CosAddrBits), [23:16] ROM 12 word bits
//   0x48 BUILD_ROM_BITS RO  ROM 12 size in bits (NumBanks * 2^CosAddrBits * word bits)
//   0x4C BUILD_FMT   RO   [7:0] CBits, [15:8] AngleBits, [23:16] NBits, [31:24] LenBits
//   0x80 + 4 j       RO   BANK_MAX_N[j], j = 0..15: the largest n of bank j (BankMaxN
//                         field j); 0 for j >= NumBanks
// Unused bits of a register read 0 and ignore writes. Reset values 0 except ID, VERSION
// and the BUILD_* / BANK_MAX_N constants.
//
// AXI4-Lite rules kept here:
//   - AW and W are accepted independently, in either order or in the same cycle, each into
//     a holding register; the write takes effect at the edge after both are held, and B is
//     valid from the next cycle. One write is outstanding at a time: awready and wready are
//     low from the acceptance of their own channel until the B transfer.
//   - AR is accepted when no read response is pending (arready = !rvalid); R is valid in
//     the next cycle. One read is outstanding at a time.
//   - bvalid/bresp and rvalid/rdata/rresp are registers and hold until their transfer;
//     every ready is a register (awready, wready, arready depend on no input).
//   - Responses: OKAY, or SLVERR for an unmapped address and for a write to a read-only
//     register (no effect). A read of PUSH is OKAY and returns 0.
//   - WSTRB: RW registers update only the byte lanes whose strobe is set; ERR clears only
//     bits in strobed lanes; PUSH needs at least one strobe bit. A write with WSTRB = 0 is
//     answered OKAY and changes nothing.
//   - AWPROT and ARPROT are ignored.
//
// Span FIFO: FifoDepth entries (default 4) of {tag, len, n, dpsi, psi0, c}. PUSH writes the
// SPAN_* registers as they are (they keep their values, so a span can be pushed again);
// the span enters the FIFO at the edge after the write (in the first cycle of its B) and
// the core can accept it in the next cycle. STATUS counts it from the write on.
// A push when the FIFO holds FifoDepth spans is dropped and sets ERR.PUSH_FULL.
// irq_o: registered, high while (ERR & IRQ_EN) != 0 (level; cleared through ERR or IRQ_EN).
//
// Parameters: those of specular_stream (rtl/core/specular_params.svh and TagBits, passed
// through), AddrWidth
// (>= 8) and FifoDepth (1 .. 255). The interface widths CBits, AngleBits, NBits, LenBits and
// TagBits must not exceed 32 (one register each).

`include "specular_assert.svh"
`include "specular_params.svh"
`include "specular_axil_ports.svh"

module specular_axil #(
  `SPECULAR_CORE_PARAMS,
  parameter int TagBits /*verilator public*/     = 16,
  parameter int AddrWidth /*verilator public*/   = 8,
  parameter int FifoDepth /*verilator public*/   = 4
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,

  // AXI4-Lite slave
  `SPECULAR_AXIL_PORTS,

  // AXI4-Stream master: pixels (as specular_axis)
  `SPECULAR_AXIS_PX_PORTS,

  output logic                 irq_o
);

  // ---------------------------------------------------------------------------------
  // Constants
  // ---------------------------------------------------------------------------------
  localparam logic [31:0] IdValue      = 32'h5350_4543;  // "SPEC"
  localparam logic [31:0] VersionValue = 32'h0001_0000;  // 1.0

  // Register word indices (byte offset / 4)
  localparam logic [5:0] RegId           = 6'h00;
  localparam logic [5:0] RegVersion      = 6'h01;
  localparam logic [5:0] RegIrqEn        = 6'h02;
  localparam logic [5:0] RegErr          = 6'h03;
  localparam logic [5:0] RegStatus       = 6'h04;
  localparam logic [5:0] RegSpans        = 6'h05;
  localparam logic [5:0] RegPixels       = 6'h06;
  localparam logic [5:0] RegSpanC        = 6'h08;
  localparam logic [5:0] RegSpanPsi0     = 6'h09;
  localparam logic [5:0] RegSpanDpsi     = 6'h0a;
  localparam logic [5:0] RegSpanN        = 6'h0b;
  localparam logic [5:0] RegSpanLen      = 6'h0c;
  localparam logic [5:0] RegSpanTag      = 6'h0d;
  localparam logic [5:0] RegPush         = 6'h0e;
  localparam logic [5:0] RegBuildCore    = 6'h10;
  localparam logic [5:0] RegBuildRom     = 6'h11;
  localparam logic [5:0] RegBuildRomBits = 6'h12;
  localparam logic [5:0] RegBuildFmt     = 6'h13;
  localparam logic [5:0] RegBankMaxN     = 6'h20;  // .. 6'h2f

  localparam logic [1:0] RespOkay   = 2'b00;
  localparam logic [1:0] RespSlverr = 2'b10;

  localparam int ErrBits   = 2;  // [0] BAD_N, [1] PUSH_FULL
  localparam int ErrBadN   = 0;
  localparam int ErrFull   = 1;

  // Build information: the core's latency (specular_pkg, docs/pipeline.md#stage-counts); the
  // testbench checks it against the latency it observes.
  localparam int Latency     = specular_pkg::stream_latency(PsiMulFrac, CosDeltaBits, CosDataBits);
  localparam int CosWordBits = CosInterp ? CosDataBits + 1 + CosDeltaBits : CosDataBits;
  localparam int RomBits     = NumBanks * (2 ** CosAddrBits) * CosWordBits;

  // Span FIFO: {tag, len, n, dpsi, psi0, c}; the low SpanBits are specular_axis's tdata.
  localparam int SpanBits     = CBits + 2 * AngleBits + NBits + LenBits;
  localparam int SpanDataBits = ((SpanBits + 7) / 8) * 8;
  localparam int FifoWidth    = TagBits + SpanBits;
  localparam int PtrBits      = (FifoDepth > 1) ? $clog2(FifoDepth) : 1;
  localparam int LevelBits    = $clog2(FifoDepth + 1);
  // Spans accepted by the core whose last pixel has not left: at most one per pipeline
  // stage and output buffer entry (Latency + 1), so 8 bits are plenty.
  localparam int InflightBits = 8;

  localparam logic [NBits-1:0] NMax = BankMaxN[NumBanks*NBits-1 -: NBits];

  if (AddrWidth < 8) begin : gen_addr_check
    `SPEC_PARAM_ERROR("specular_axil: AddrWidth must be >= 8 (the register map spans 0x00 .. 0xBC)")
  end
  if (FifoDepth < 1 || FifoDepth > 255) begin : gen_fifo_check
    `SPEC_PARAM_ERROR("specular_axil: FifoDepth must be 1 .. 255")
  end
  if (CBits > 32 || AngleBits > 32 || NBits > 32 || LenBits > 32 || TagBits > 32) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_axil: CBits, AngleBits, NBits, LenBits and TagBits must be <= 32")
  end
  if (NumBanks > 16) begin : gen_banks_check
    `SPEC_PARAM_ERROR("specular_axil: BANK_MAX_N shows at most 16 banks")
  end
  if (Latency > 255) begin : gen_latency_check
    `SPEC_PARAM_ERROR("specular_axil: Latency does not fit BUILD_CORE[7:0]")
  end

  // Byte lanes of WSTRB applied to a 32-bit register value.
  function automatic logic [31:0] strb_merge(input logic [31:0] old, input logic [31:0] data,
                                             input logic [3:0] strb);
    for (int b = 0; b < 4; b++) begin
      strb_merge[8*b +: 8] = strb[b] ? data[8*b +: 8] : old[8*b +: 8];
    end
  endfunction

  // ---------------------------------------------------------------------------------
  // Registers of the map
  // ---------------------------------------------------------------------------------
  logic [ErrBits-1:0]   irq_en_q, irq_en_d, err_q, err_d;
  logic [CBits-1:0]     span_c_q, span_c_d;
  logic [AngleBits-1:0] span_psi0_q, span_psi0_d, span_dpsi_q, span_dpsi_d;
  logic [NBits-1:0]     span_n_q, span_n_d;
  logic [LenBits-1:0]   span_len_q, span_len_d;
  logic [TagBits-1:0]   span_tag_q, span_tag_d;
  logic [31:0]          spans_q, spans_d, pixels_q, pixels_d;
  logic                 irq_q, irq_d;

  // FIFO and core state
  logic [FifoWidth-1:0]    fifo_mem_q [FifoDepth];
  logic [PtrBits-1:0]      wr_ptr_q, wr_ptr_d, rd_ptr_q, rd_ptr_d;
  logic [LevelBits-1:0]    level_q, level_d;
  logic [InflightBits-1:0] inflight_q, inflight_d;
  logic                    fifo_full, push, pop, busy;
  logic                    fifo_wr_q;  // the span pushed at the last edge enters the FIFO
  logic [LevelBits-1:0]    level_shown;
  logic                    core_span_tready, px_fire;

  // A PUSH is decided at the write's edge (counters, errors) and enters the FIFO at the
  // next edge (fifo_wr_q): the FIFO's write enable then comes from a register, not from
  // the write decode (iCE40: that enable drives every FIFO flip-flop through a global
  // buffer). The SPAN_* registers cannot change in between (the next write takes effect
  // three clocks later at the earliest), and neither can the level seen by the next PUSH.
  assign fifo_full   = level_q == LevelBits'(FifoDepth);
  assign level_shown = level_q + LevelBits'(fifo_wr_q);
  assign busy        = (level_shown != '0) || (inflight_q != '0);

  // ---------------------------------------------------------------------------------
  // Write channels: AW and W holding registers, the write, B
  // ---------------------------------------------------------------------------------
  logic                 aw_full_q, aw_full_d, w_full_q, w_full_d;
  logic [AddrWidth-1:0] awaddr_q, awaddr_d;
  logic [31:0]          wdata_q, wdata_d;
  logic [3:0]           wstrb_q, wstrb_d;
  logic                 bvalid_q, bvalid_d;
  logic [1:0]           bresp_q, bresp_d;
  logic                 aw_fire, w_fire, do_write;
  logic [5:0]           wr_word;
  logic                 wr_in_window;

  assign s_axil_awready = ~aw_full_q & ~bvalid_q;
  assign s_axil_wready  = ~w_full_q & ~bvalid_q;
  assign aw_fire        = s_axil_awvalid & s_axil_awready;
  assign w_fire         = s_axil_wvalid & s_axil_wready;
  assign do_write       = aw_full_q & w_full_q & ~bvalid_q;
  assign wr_word        = awaddr_q[7:2];
  assign wr_in_window   = (awaddr_q >> 8) == '0;

  always_comb begin
    aw_full_d = aw_full_q;
    awaddr_d  = awaddr_q;
    w_full_d  = w_full_q;
    wdata_d   = wdata_q;
    wstrb_d   = wstrb_q;
    bvalid_d  = bvalid_q;
    bresp_d   = bresp_q;
    if (aw_fire) begin
      aw_full_d = 1'b1;
      awaddr_d  = s_axil_awaddr;
    end
    if (w_fire) begin
      w_full_d = 1'b1;
      wdata_d  = s_axil_wdata;
      wstrb_d  = s_axil_wstrb;
    end
    if (s_axil_bvalid && s_axil_bready) begin
      bvalid_d = 1'b0;
    end
    if (do_write) begin
      aw_full_d = 1'b0;
      w_full_d  = 1'b0;
      bvalid_d  = 1'b1;
      bresp_d   = RespSlverr;
      if (wr_in_window) begin
        unique case (wr_word)
          RegIrqEn, RegErr, RegSpanC, RegSpanPsi0, RegSpanDpsi, RegSpanN, RegSpanLen,
          RegSpanTag, RegPush: bresp_d = RespOkay;
          default: bresp_d = RespSlverr;  // read-only or unmapped
        endcase
      end
    end
  end

  // Register writes, PUSH, error bits, counters
  logic        wr_okay;
  logic [31:0] wr_merged;
  logic [31:0] wr_old;

  assign wr_okay = do_write && wr_in_window;

  always_comb begin
    unique case (wr_word)
      RegIrqEn:    wr_old = 32'(irq_en_q);
      RegSpanC:    wr_old = 32'(span_c_q);
      RegSpanPsi0: wr_old = 32'(span_psi0_q);
      RegSpanDpsi: wr_old = 32'(span_dpsi_q);
      RegSpanN:    wr_old = 32'(span_n_q);
      RegSpanLen:  wr_old = 32'(span_len_q);
      RegSpanTag:  wr_old = 32'(span_tag_q);
      default:     wr_old = '0;
    endcase
  end
  assign wr_merged = strb_merge(wr_old, wdata_q, wstrb_q);

  logic [ErrBits-1:0] err_clear;
  logic               push_req, bad_n;

  assign push_req  = wr_okay && (wr_word == RegPush) && (wstrb_q != 4'b0000);
  assign push      = push_req && !fifo_full;
  assign bad_n     = (span_n_q == '0) || (span_n_q > NMax);
  // The error bits sit in byte lane 0.
  assign err_clear = (wr_okay && wr_word == RegErr && wstrb_q[0]) ? wdata_q[ErrBits-1:0] : '0;

  always_comb begin
    irq_en_d    = irq_en_q;
    span_c_d    = span_c_q;
    span_psi0_d = span_psi0_q;
    span_dpsi_d = span_dpsi_q;
    span_n_d    = span_n_q;
    span_len_d  = span_len_q;
    span_tag_d  = span_tag_q;
    if (wr_okay) begin
      unique case (wr_word)
        RegIrqEn:    irq_en_d    = wr_merged[ErrBits-1:0];
        RegSpanC:    span_c_d    = wr_merged[CBits-1:0];
        RegSpanPsi0: span_psi0_d = wr_merged[AngleBits-1:0];
        RegSpanDpsi: span_dpsi_d = wr_merged[AngleBits-1:0];
        RegSpanN:    span_n_d    = wr_merged[NBits-1:0];
        RegSpanLen:  span_len_d  = wr_merged[LenBits-1:0];
        RegSpanTag:  span_tag_d  = wr_merged[TagBits-1:0];
        default: ;
      endcase
    end
    // Sticky errors: a new error wins over a clear in the same edge.
    err_d = err_q & ~err_clear;
    if (push && bad_n) err_d[ErrBadN] = 1'b1;
    if (push_req && fifo_full) err_d[ErrFull] = 1'b1;
    irq_d = |(err_d & irq_en_d);
    // Counters: the increment is a constant-carry chain, the event only selects it (an
    // event fed into the carry chain would ripple through all 32 bits).
    spans_d  = push ? spans_q + 32'd1 : spans_q;
    pixels_d = px_fire ? pixels_q + 32'd1 : pixels_q;
  end

  // ---------------------------------------------------------------------------------
  // Read channel: AR, the register read, R
  // ---------------------------------------------------------------------------------
  logic        rvalid_q, rvalid_d;
  logic [31:0] rdata_q, rdata_d, rd_value;
  logic [1:0]  rresp_q, rresp_d;
  logic        ar_fire, rd_err;
  logic [5:0]  rd_word;

  assign s_axil_arready = ~rvalid_q;
  assign ar_fire        = s_axil_arvalid & s_axil_arready;
  assign rd_word        = s_axil_araddr[7:2];

  always_comb begin
    rd_value = '0;
    rd_err   = 1'b0;
    unique case (rd_word)
      RegId:           rd_value = IdValue;
      RegVersion:      rd_value = VersionValue;
      RegIrqEn:        rd_value = 32'(irq_en_q);
      RegErr:          rd_value = 32'(err_q);
      RegStatus:       rd_value = {21'b0, irq_q, busy, level_shown == LevelBits'(FifoDepth), 8'(level_shown)};
      RegSpans:        rd_value = spans_q;
      RegPixels:       rd_value = pixels_q;
      RegSpanC:        rd_value = 32'(span_c_q);
      RegSpanPsi0:     rd_value = 32'(span_psi0_q);
      RegSpanDpsi:     rd_value = 32'(span_dpsi_q);
      RegSpanN:        rd_value = 32'(span_n_q);
      RegSpanLen:      rd_value = 32'(span_len_q);
      RegSpanTag:      rd_value = 32'(span_tag_q);
      RegPush:         rd_value = '0;
      RegBuildCore:    rd_value = {7'b0, CosInterp, 8'(TagBits), 8'(FifoDepth), 8'(Latency)};
      RegBuildRom:     rd_value = {8'b0, 8'(CosWordBits), 8'(CosAddrBits), 8'(NumBanks)};
      RegBuildRomBits: rd_value = 32'(RomBits);
      RegBuildFmt:     rd_value = {8'(LenBits), 8'(NBits), 8'(AngleBits), 8'(CBits)};
      default: begin
        if (rd_word[5:4] == RegBankMaxN[5:4]) begin
          // BANK_MAX_N[j]: 0 beyond the last bank
          for (int j = 0; j < NumBanks; j++) begin
            if (rd_word[3:0] == 4'(j)) rd_value = 32'(BankMaxN[j*NBits +: NBits]);
          end
        end else begin
          rd_err = 1'b1;
        end
      end
    endcase
    if ((s_axil_araddr >> 8) != '0) begin
      rd_value = '0;
      rd_err   = 1'b1;
    end
  end

  always_comb begin
    rvalid_d = rvalid_q;
    rdata_d  = rdata_q;
    rresp_d  = rresp_q;
    if (s_axil_rvalid && s_axil_rready) begin
      rvalid_d = 1'b0;
    end
    if (ar_fire) begin
      rvalid_d = 1'b1;
      rdata_d  = rd_value;
      rresp_d  = rd_err ? RespSlverr : RespOkay;
    end
  end

  // ---------------------------------------------------------------------------------
  // Span FIFO
  // ---------------------------------------------------------------------------------
  logic [FifoWidth-1:0] fifo_head;

  assign fifo_head = fifo_mem_q[rd_ptr_q];
  assign pop       = (level_q != '0) && core_span_tready;

  always_comb begin
    wr_ptr_d = wr_ptr_q;
    rd_ptr_d = rd_ptr_q;
    if (fifo_wr_q) wr_ptr_d = (wr_ptr_q == PtrBits'(FifoDepth - 1)) ? '0 : wr_ptr_q + PtrBits'(1);
    if (pop)       rd_ptr_d = (rd_ptr_q == PtrBits'(FifoDepth - 1)) ? '0 : rd_ptr_q + PtrBits'(1);
    level_d = level_q + LevelBits'(fifo_wr_q) - LevelBits'(pop);
  end

  // The FIFO words have no reset (they are read only while the level is non-zero).
  always_ff @(posedge clk_i) begin
    if (fifo_wr_q) begin
      fifo_mem_q[wr_ptr_q] <= {span_tag_q, span_len_q, span_n_q, span_dpsi_q, span_psi0_q, span_c_q};
    end
  end

  // ---------------------------------------------------------------------------------
  // The stream core with AXI4-Stream ports
  // ---------------------------------------------------------------------------------
  logic [SpanDataBits-1:0] core_span_tdata;

  assign core_span_tdata = SpanDataBits'(fifo_head[SpanBits-1:0]);  // zero pad

  specular_axis #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits      (TagBits)
  ) u_axis (
    .clk_i              (clk_i),
    .rst_ni             (rst_ni),
    .s_axis_span_tdata  (core_span_tdata),
    .s_axis_span_tuser  (fifo_head[FifoWidth-1 -: TagBits]),
    .s_axis_span_tvalid (level_q != '0),
    .s_axis_span_tready (core_span_tready),
    `SPECULAR_AXIS_PX_MAP(m_axis_px_)
  );

  assign px_fire    = m_axis_px_tvalid && m_axis_px_tready;
  assign inflight_d = inflight_q + InflightBits'(pop) - InflightBits'(px_fire && m_axis_px_tlast);

  // ---------------------------------------------------------------------------------
  // State
  // ---------------------------------------------------------------------------------
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      aw_full_q   <= 1'b0;
      awaddr_q    <= '0;
      w_full_q    <= 1'b0;
      wdata_q     <= '0;
      wstrb_q     <= '0;
      bvalid_q    <= 1'b0;
      bresp_q     <= RespOkay;
      rvalid_q    <= 1'b0;
      rdata_q     <= '0;
      rresp_q     <= RespOkay;
      irq_en_q    <= '0;
      err_q       <= '0;
      irq_q       <= 1'b0;
      span_c_q    <= '0;
      span_psi0_q <= '0;
      span_dpsi_q <= '0;
      span_n_q    <= '0;
      span_len_q  <= '0;
      span_tag_q  <= '0;
      spans_q     <= '0;
      pixels_q    <= '0;
      wr_ptr_q    <= '0;
      rd_ptr_q    <= '0;
      level_q     <= '0;
      fifo_wr_q   <= 1'b0;
      inflight_q  <= '0;
    end else begin
      aw_full_q   <= aw_full_d;
      awaddr_q    <= awaddr_d;
      w_full_q    <= w_full_d;
      wdata_q     <= wdata_d;
      wstrb_q     <= wstrb_d;
      bvalid_q    <= bvalid_d;
      bresp_q     <= bresp_d;
      rvalid_q    <= rvalid_d;
      rdata_q     <= rdata_d;
      rresp_q     <= rresp_d;
      irq_en_q    <= irq_en_d;
      err_q       <= err_d;
      irq_q       <= irq_d;
      span_c_q    <= span_c_d;
      span_psi0_q <= span_psi0_d;
      span_dpsi_q <= span_dpsi_d;
      span_n_q    <= span_n_d;
      span_len_q  <= span_len_d;
      span_tag_q  <= span_tag_d;
      spans_q     <= spans_d;
      pixels_q    <= pixels_d;
      wr_ptr_q    <= wr_ptr_d;
      rd_ptr_q    <= rd_ptr_d;
      level_q     <= level_d;
      fifo_wr_q   <= push;
      inflight_q  <= inflight_d;
    end
  end

  assign s_axil_bvalid = bvalid_q;
  assign s_axil_bresp  = bresp_q;
  assign s_axil_rvalid = rvalid_q;
  assign s_axil_rdata  = rdata_q;
  assign s_axil_rresp  = rresp_q;
  assign irq_o         = irq_q;

  logic unused_prot;
  assign unused_prot = ^{s_axil_awprot, s_axil_arprot};

endmodule
