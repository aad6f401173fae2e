// SPDX-License-Identifier: Apache-2.0
//
// specular_axil: an AXI4-Lite slave (32-bit data) in front of the stream core. The CPU
// writes a span descriptor into registers and pushes it into a span FIFO; the FIFO feeds
// specular_axis (specular_stream with AXI4-Stream ports, rtl/axi/specular_axis.sv), whose pixels
// leave on the AXI4-Stream master m_axis_px_*. The port table and the bus rules are in
// docs/interfaces.md; this header is authoritative where they differ.
//
// Register map: written once, in rtl/axi/data/specular_axil.rdl (SystemRDL: offsets,
// fields, access, reset values), from which scripts/regmap.py generates the constants this
// module decodes with (specular_axil_reg_pkg, rtl/axi/specular_axil_reg_pkg.sv), the C
// header of the tests and hosts, and the table of docs/interfaces.md#register-map. Byte
// offsets; 32-bit registers; address bits [1:0] are ignored; the map's window is
// 2^BlockAw bytes (0x00 .. 0xFF), addresses above it (AddrWidth > 8) are unmapped. Unused
// bits of a register read 0 and ignore writes.
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
//     register (no effect), as the map's access types say (specular_axil_reg_pkg's
//     ReadableWords and WritableWords). A read of PUSH is OKAY and returns 0.
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
  // The register map's offsets, field positions, constants and access types are those of
  // specular_axil_reg_pkg (generated from rtl/axi/data/specular_axil.rdl, see the header);
  // MapAw is the width of the map's window.
  localparam int MapAw = specular_axil_reg_pkg::BlockAw;

  localparam logic [1:0] RespOkay   = 2'b00;
  localparam logic [1:0] RespSlverr = 2'b10;

  // ERR and IRQ_EN have the same fields, BAD_N and PUSH_FULL, from bit 0 up.
  localparam int ErrBits = 2;
  localparam int ErrBadN = specular_axil_reg_pkg::ErrBadNLsb;
  localparam int ErrFull = specular_axil_reg_pkg::ErrPushFullLsb;

  // Build information: the core's latency (specular_pkg, docs/pipeline.md#stage-counts); the
  // testbench checks it against the latency it observes.
  localparam int Latency     = specular_pkg::stream_latency(PsiMulFrac, CosDeltaBits, CosDataBits, Blend);
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

  if (AddrWidth < MapAw) begin : gen_addr_check
    `SPEC_PARAM_ERROR("specular_axil: AddrWidth must be >= 8 (the register map spans 0x00 .. 0xBC)")
  end
  if (ErrBadN != specular_axil_reg_pkg::IrqEnBadNLsb ||
      ErrFull != specular_axil_reg_pkg::IrqEnPushFullLsb ||
      ErrBits != specular_axil_reg_pkg::ErrPushFullLsb + 1) begin : gen_err_check
    `SPEC_PARAM_ERROR("specular_axil: ERR and IRQ_EN must hold BAD_N and PUSH_FULL in bits 0 and 1")
  end
  if (FifoDepth < 1 || FifoDepth > 255) begin : gen_fifo_check
    `SPEC_PARAM_ERROR("specular_axil: FifoDepth must be 1 .. 255")
  end
  if (CBits > 32 || AngleBits > 32 || NBits > 32 || LenBits > 32 || TagBits > 32) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_axil: CBits, AngleBits, NBits, LenBits and TagBits must be <= 32")
  end
  if (NumBanks > specular_axil_reg_pkg::BankMaxNCount) begin : gen_banks_check
    `SPEC_PARAM_ERROR("specular_axil: BANK_MAX_N shows at most 16 banks")
  end
  if (Latency > 255) begin : gen_latency_check
    `SPEC_PARAM_ERROR("specular_axil: Latency does not fit BUILD_CORE[7:0]")
  end
  // The register map has one SPAN_C register: an RGB span would need a map change.
  if (Channels != 1) begin : gen_channels_check
    `SPEC_PARAM_ERROR("specular_axil: Channels must be 1 (the register map has one SPAN_C; RGB spans: specular_axis)")
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
  logic [MapAw-1:0]     wr_offset;  // byte offset of the word written, in the window
  logic                 wr_in_window;

  assign s_axil_awready = ~aw_full_q & ~bvalid_q;
  assign s_axil_wready  = ~w_full_q & ~bvalid_q;
  assign aw_fire        = s_axil_awvalid & s_axil_awready;
  assign w_fire         = s_axil_wvalid & s_axil_wready;
  assign do_write       = aw_full_q & w_full_q & ~bvalid_q;
  assign wr_offset      = {awaddr_q[MapAw-1:2], 2'b00};
  assign wr_in_window   = (awaddr_q >> MapAw) == '0;

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
        // The map's words with a writable field (RW, W1C, WO).
        unique case (specular_axil_reg_pkg::WritableWords[wr_offset[MapAw-1:2]])
          1'b1:    bresp_d = RespOkay;
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
    unique case (wr_offset)
      specular_axil_reg_pkg::IrqEnOffset:    wr_old = 32'(irq_en_q);
      specular_axil_reg_pkg::SpanCOffset:    wr_old = 32'(span_c_q);
      specular_axil_reg_pkg::SpanPsi0Offset: wr_old = 32'(span_psi0_q);
      specular_axil_reg_pkg::SpanDpsiOffset: wr_old = 32'(span_dpsi_q);
      specular_axil_reg_pkg::SpanNOffset:    wr_old = 32'(span_n_q);
      specular_axil_reg_pkg::SpanLenOffset:  wr_old = 32'(span_len_q);
      specular_axil_reg_pkg::SpanTagOffset:  wr_old = 32'(span_tag_q);
      default:                               wr_old = '0;
    endcase
  end
  assign wr_merged = strb_merge(wr_old, wdata_q, wstrb_q);

  logic [ErrBits-1:0] err_clear;
  logic               push_req, bad_n;

  assign push_req  = wr_okay && (wr_offset == specular_axil_reg_pkg::PushOffset) &&
                     (wstrb_q != 4'b0000);
  assign push      = push_req && !fifo_full;
  assign bad_n     = (span_n_q == '0) || (span_n_q > NMax);
  // The error bits sit in byte lane 0.
  assign err_clear = (wr_okay && wr_offset == specular_axil_reg_pkg::ErrOffset && wstrb_q[0]) ?
                     wdata_q[ErrBits-1:0] : '0;

  always_comb begin
    irq_en_d    = irq_en_q;
    span_c_d    = span_c_q;
    span_psi0_d = span_psi0_q;
    span_dpsi_d = span_dpsi_q;
    span_n_d    = span_n_q;
    span_len_d  = span_len_q;
    span_tag_d  = span_tag_q;
    if (wr_okay) begin
      unique case (wr_offset)
        specular_axil_reg_pkg::IrqEnOffset:    irq_en_d    = wr_merged[ErrBits-1:0];
        specular_axil_reg_pkg::SpanCOffset:    span_c_d    = wr_merged[CBits-1:0];
        specular_axil_reg_pkg::SpanPsi0Offset: span_psi0_d = wr_merged[AngleBits-1:0];
        specular_axil_reg_pkg::SpanDpsiOffset: span_dpsi_d = wr_merged[AngleBits-1:0];
        specular_axil_reg_pkg::SpanNOffset:    span_n_d    = wr_merged[NBits-1:0];
        specular_axil_reg_pkg::SpanLenOffset:  span_len_d  = wr_merged[LenBits-1:0];
        specular_axil_reg_pkg::SpanTagOffset:  span_tag_d  = wr_merged[TagBits-1:0];
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
  logic             rvalid_q, rvalid_d;
  logic [31:0]      rdata_q, rdata_d, rd_value;
  logic [1:0]       rresp_q, rresp_d;
  logic             ar_fire, rd_err;
  logic [MapAw-1:0] rd_offset;  // byte offset of the word read, in the window

  assign s_axil_arready = ~rvalid_q;
  assign ar_fire        = s_axil_arvalid & s_axil_arready;
  assign rd_offset      = {s_axil_araddr[MapAw-1:2], 2'b00};

  // A read answers SLVERR outside the map's words and above its window, with 0 (as every
  // unused bit of a register).
  always_comb begin
    rd_value = '0;
    rd_err   = !specular_axil_reg_pkg::ReadableWords[rd_offset[MapAw-1:2]];
    unique case (rd_offset)
      specular_axil_reg_pkg::IdOffset:       rd_value = specular_axil_reg_pkg::IdReset;
      specular_axil_reg_pkg::VersionOffset:  rd_value = specular_axil_reg_pkg::VersionReset;
      specular_axil_reg_pkg::IrqEnOffset:    rd_value = 32'(irq_en_q);
      specular_axil_reg_pkg::ErrOffset:      rd_value = 32'(err_q);
      specular_axil_reg_pkg::StatusOffset:
        rd_value = specular_axil_reg_pkg::status_value(8'(level_shown),
                                                       level_shown == LevelBits'(FifoDepth),
                                                       busy, irq_q);
      specular_axil_reg_pkg::SpansOffset:    rd_value = spans_q;
      specular_axil_reg_pkg::PixelsOffset:   rd_value = pixels_q;
      specular_axil_reg_pkg::SpanCOffset:    rd_value = 32'(span_c_q);
      specular_axil_reg_pkg::SpanPsi0Offset: rd_value = 32'(span_psi0_q);
      specular_axil_reg_pkg::SpanDpsiOffset: rd_value = 32'(span_dpsi_q);
      specular_axil_reg_pkg::SpanNOffset:    rd_value = 32'(span_n_q);
      specular_axil_reg_pkg::SpanLenOffset:  rd_value = 32'(span_len_q);
      specular_axil_reg_pkg::SpanTagOffset:  rd_value = 32'(span_tag_q);
      specular_axil_reg_pkg::BuildCoreOffset:
        rd_value = specular_axil_reg_pkg::build_core_value(8'(Latency), 8'(FifoDepth),
                                                           8'(TagBits), CosInterp);
      specular_axil_reg_pkg::BuildRomOffset:
        rd_value = specular_axil_reg_pkg::build_rom_value(8'(NumBanks), 8'(CosAddrBits),
                                                          8'(CosWordBits));
      specular_axil_reg_pkg::BuildRomBitsOffset: rd_value = 32'(RomBits);
      specular_axil_reg_pkg::BuildFmtOffset:
        rd_value = specular_axil_reg_pkg::build_fmt_value(8'(CBits), 8'(AngleBits), 8'(NBits),
                                                          8'(LenBits));
      default: begin
        // BANK_MAX_N[j]: field j of BankMaxN, 0 beyond the last bank
        for (int j = 0; j < NumBanks; j++) begin
          if (rd_offset == specular_axil_reg_pkg::BankMaxNOffset + MapAw'(4 * j)) begin
            rd_value = 32'(BankMaxN[j*NBits +: NBits]);
          end
        end
      end
    endcase
    if ((s_axil_araddr >> MapAw) != '0) begin
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
