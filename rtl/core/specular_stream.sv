// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_stream: the device of patent UA 71489 as a streaming pixel pipeline. Span
// descriptors (the register values of one scanline) come in, pixels go out, each side with
// a valid/ready handshake. For span (C, psi0, dpsi, n, l, tag) pixel i = 0..l is
//   I_i = C * cos^k(a(n) * psi_i),  psi_i = psi0 + i * dpsi,   0 where a*|psi_i| >= pi/2,
// bit-identical to specular_unit with the same register values (one datapath: specular_unit
// is a wrapper over this module). Bit-exact contract: model/device/device_model.hpp.
//
// Ports (default widths; formats those of specular_unit's registers):
//   clk_i, rst_ni                clock; asynchronous reset, active low: drops every span and
//                                pixel in flight, the core is empty afterwards
//   span_valid_i, span_ready_o   span handshake
//   span_c_i[16]                 C, unsigned, 15 fraction bits (Channels of them, channel 0
//                                in the low bits: 48 bits with Channels = 3)
//   span_psi0_i[32], span_dpsi_i[32]  psi0 and dpsi, radians, signed, 28 fraction bits
//   span_n_i[10]                 n, 1..1000 (0 or > 1000: every pixel of the span 0)
//   span_len_i[11]               l: the span has l + 1 pixels
//   span_tag_i[TagBits]          opaque, returned with every pixel of the span
//   px_valid_o, px_ready_i       pixel handshake
//   px_intensity_o[16]           pixel intensity, format of C; 0 while px_valid_o is low
//                                (Channels of them, channel ch = round(C_ch * cos^k))
//   px_last_o                    the pixel is pixel l of its span
//   px_tag_o[TagBits]            the tag of the pixel's span
//
// Handshake, AXI4-Stream rules: a transfer happens at a rising edge where valid and ready
// are both high. px_valid_o and the pixel are registers; once px_valid_o is high they hold
// until the transfer, and px_valid_o never waits for px_ready_i.
// span_ready_o depends on registers only (never on span_valid_i or px_ready_i): it is high
// when the pipeline advances at the next edge (the two-entry output buffer has room,
// specular_out_buf) and register 8 is empty or holds its span's last pixel. px_ready_i
// reaches only the output buffer's flip-flops.
//
// Timing: a span accepted at the edge ending cycle t has pixel i on the output in cycle
// t + L + i, L = specular_pkg::stream_latency (PipeDepth stages plus the output buffer; the
// figures per configuration: docs/pipeline.md#stage-counts) when px_ready_i stays high;
// the next span's pixel 0
// follows its previous span's last pixel in the next cycle, whatever l (one pixel per
// clock sustained, no bubble between spans). Stalls (px_ready_i low) freeze every stage.
//
// Pipeline (patent block numbers), every stage register enabled by adv, a register of the
// output buffer (high while it has room; with px_ready_i high always):
//   stage 0  registers 1 (C), 2 (dpsi), 4 (n), counter 5 and the tag load when a span is
//            accepted; register 8 (accumulator 6/7/8) takes psi0 then psi + dpsi; ROM 9 is
//            read with the span's n at the accept edge; decoder 10 decodes register 4
//   stage 1       register 8, high half (specular_accumulator splits the 44-bit add)
//   then          multiplier 11: |psi| and pi/2 test, the multiplier tree over the bits of
//                 |psi|, the ROM 12 address / weight / zero flag
//   then          ROM 12: block RAM read, interpolation tree d * t, cos^k = v - d t (the
//                 direct table is delayed as long)
//   then          (Blend = 1 only) specular_blend: cos_b = c1 + ((c2 - c1) w + 2^(W-1)) >> W of
//                 the two reads, docs/display_exact.md
//   then          multiplier 13: radix-4 tree over cos^k, rounding and the output register
//                 (output 27)
//   output buffer two entries (specular_out_buf): the pixel handshake
// (each block's stage count follows its parameters: specular_pkg, docs/pipeline.md#stage-counts).
// Every stage holds at most one carry chain: the clock period is bounded by one adder and
// its routing, never by two adders in series (rtl/fpga/README.md).
// C, the tag, the bank and the n-valid flag of each pixel travel beside it (specular_delay), so every
// pixel uses its own span's values while consecutive spans overlap in the pipeline.
// Register 3 (psi0) is the span bus itself: mux 7 takes psi0 straight from span_psi0_i.
//
// Patent errata resolved here (docs/device.md): n has 10 bits; registers 3 and 2 hold the
// unscaled -lambda and gamma/l (multiplier 11 applies a(n)); ROM 12 covers only [0, pi/2),
// |zeta| addresses it and zeta >= pi/2 outputs 0.
//
// Blend = 1 (the display-exact builds, docs/display_exact.md): ROM 9's word is {a1, a2, w};
// decoder 10's bank j and the next (j itself for the last) are read by two multipliers 11 and
// two reads of ROM 12 (a second block RAM port), each 0 past its bank's domain, and blended
// before multiplier 13. Same handshake and one pixel per clock; more stages.
//
// Channels = 3 (RGB): a span's C is a colour, one C register, 3C register and C delay line
// per channel; the pixel's one cos^k (or blend) feeds one multiplier 13 per channel, side by
// side, so the stage counts, the latency and one pixel per clock are those of Channels = 1,
// and channel ch is the pixel of Channels = 1 with C = C_ch.
//
// Parameters: the core's list, written once in rtl/core/specular_params.svh (widths, ROM
// files, decoder banks; defaults those of specular::device::Format), and TagBits.

`include "specular_assert.svh"
`include "specular_params.svh"
`include "specular_span_ports.svh"

module specular_stream #(
  `SPECULAR_CORE_PARAMS,
  parameter int TagBits     = 16
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_SPAN_PORTS_CH(input, output, _i, _o, Channels),
  `SPECULAR_PX_PORTS_CH(Channels)
);

  // Stage counts of the blocks and of the whole pipeline: specular_pkg, their one
  // definition (docs/pipeline.md#stage-counts).
  localparam int AccStages   = specular_pkg::AccStages;
  localparam int Mul11Stages = specular_pkg::angle_mul_stages(PsiMulFrac);
  localparam int Rom12Stages = specular_pkg::cos_k_rom_stages(CosDeltaBits);
  localparam int BlendStages = specular_pkg::blend_stages(Blend, CosDataBits);
  localparam int PipeDepth   = specular_pkg::stream_pipe_depth(PsiMulFrac, CosDeltaBits, CosDataBits, Blend);
  // The blend (docs/display_exact.md): two reads per pixel, ROM 9 words {a1, a2, w}.
  localparam int Reads       = Blend ? 2 : 1;
  localparam int CoefWord    = Blend ? 2 * CoefBits + WeightBits : CoefBits;
  if (specular_pkg::OutBufStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_stream: the output buffer is one register (specular_pkg::OutBufStages)")
  end

  if (CFrac > CBits) begin : gen_c_check
    `SPEC_PARAM_ERROR("specular_stream: CFrac must not exceed CBits")
  end
  if (AccBits < AngleBits + LenBits + 1) begin : gen_acc_check
    `SPEC_PARAM_ERROR("specular_stream: AccBits too small for 2^LenBits additions of dpsi")
  end
  if (Blend && (WeightBits < 1 || WeightBits > 24)) begin : gen_weight_check
    `SPEC_PARAM_ERROR("specular_stream: WeightBits must be 1..24 with Blend")
  end
  if (TagBits < 1) begin : gen_tag_check
    `SPEC_PARAM_ERROR("specular_stream: TagBits must be >= 1")
  end
  if (Channels != 1 && Channels != 3) begin : gen_channels_check
    `SPEC_PARAM_ERROR("specular_stream: Channels must be 1 (one C) or 3 (an RGB C per span)")
  end

  // ---------------------------------------------------------------------------------
  // Control unit 14
  // ---------------------------------------------------------------------------------
  logic adv, accept, unused_strobe, mux_sel, count, cnt_zero, out_valid, out_last;
  logic [PipeDepth-1:0] stage_valid;
  logic unused_busy;

  specular_control #(
    .PipeDepth (PipeDepth)
  ) u_control14 (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    .span_valid_i  (span_valid_i),
    .span_ready_o  (span_ready_o),
    .adv_i         (adv),
    .cnt_zero_i    (cnt_zero),
    .accept_o      (accept),
    .strobe_o      (unused_strobe),
    .sel_o         (mux_sel),
    .count_o       (count),
    .stage_valid_o (stage_valid),
    .out_valid_o   (out_valid),
    .out_last_o    (out_last),
    .busy_o        (unused_busy)
  );

  // ---------------------------------------------------------------------------------
  // Stage 0: registers 1, 2, 4, the tag and counter 5 load with an accepted span
  // ---------------------------------------------------------------------------------
  logic [Channels*CBits-1:0] c0;  // channel ch in bits [ch*CBits +: CBits]
  logic [AngleBits-1:0] dpsi0;
  logic [NBits-1:0]     n0;
  logic [TagBits-1:0]   tag0;
  logic [LenBits-1:0]   cnt0;
  logic                 unused_borrow, unused_cnt;

  specular_reg #(.Width (Channels * CBits)) u_reg1_c (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (accept),
    .d_i    (span_c_i),
    .q_o    (c0)
  );

  // 3C for multiplier 13's radix-4 digits, computed once per span (per channel).
  logic [Channels*(CBits+2)-1:0] c3_span, c30;
  for (genvar ch = 0; ch < Channels; ch++) begin : gen_c3
    assign c3_span[ch*(CBits+2) +: CBits+2] = (CBits + 2)'(span_c_i[ch*CBits +: CBits])
                                             + ((CBits + 2)'(span_c_i[ch*CBits +: CBits]) << 1);
  end
  specular_reg #(.Width (Channels * (CBits + 2))) u_reg1_c3 (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (accept),
    .d_i    (c3_span),
    .q_o    (c30)
  );

  specular_reg #(.Width (AngleBits)) u_reg2_dpsi (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (accept),
    .d_i    (span_dpsi_i),
    .q_o    (dpsi0)
  );

  specular_reg #(.Width (NBits)) u_reg4_n (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (accept),
    .d_i    (span_n_i),
    .q_o    (n0)
  );

  specular_reg #(.Width (TagBits)) u_reg_tag (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (accept),
    .d_i    (span_tag_i),
    .q_o    (tag0)
  );

  // The borrow equals count && cnt_zero; the control unit uses cnt_zero directly because
  // span_ready_o must be known before the edge at which the count pulse is given.
  assign unused_cnt = ^cnt0;
  specular_down_counter #(.LenBits (LenBits)) u_counter5 (
    .clk_i    (clk_i),
    .rst_ni   (rst_ni),
    .len_we_i (accept),
    .len_i    (span_len_i),
    .count_i  (count),
    .borrow_o (unused_borrow),
    .zero_o   (cnt_zero),
    .count_o  (cnt0)
  );

  // Accumulator: adder 6, mux 7, register 8 (psi of the pixel in stage 1)
  logic signed [AccBits-1:0] psi1;

  specular_accumulator #(
    .AngleBits (AngleBits),
    .AccBits   (AccBits)
  ) u_accumulator (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (adv),       // every advance: where strobe 37 is low, stage A's pixel is invalid
    .sel_i  (mux_sel),
    .step_i (count),
    .psi0_i (span_psi0_i),
    .dpsi_i (dpsi0),
    .psi_o  (psi1)
  );

  // Decoder 10 (on register 4, registered: its outputs belong to the pixel in stage 1) and
  // coefficient ROM 9 (read with the span's n on accept)
  logic [NumBanks-1:0] bank1;
  logic                n_valid1;
  logic [CoefWord-1:0] coef0;

  specular_decoder #(
    .NBits      (NBits),
    .NumBanks   (NumBanks),
    .BankMaxN   (BankMaxN),
    .Registered (1'b1)
  ) u_decoder10 (
    .clk_i     (clk_i),
    .en_i      (adv),
    .n_i       (n0),
    .bank_o    (bank1),
    .n_valid_o (n_valid1)
  );

  specular_coef_rom #(
    .NBits       (NBits),
    .CoefBits    (CoefWord),
    .CoefRomFile (CoefRomFile)
  ) u_coef_rom9 (
    .clk_i  (clk_i),
    .en_i   (accept),
    .n_i    (span_n_i),
    .coef_o (coef0)
  );

  // ---------------------------------------------------------------------------------
  // Per-pixel span values beside the datapath: each reaches its block with its pixel
  // ---------------------------------------------------------------------------------
  // ROM 9's fields: a (a1 with the blend) in the top bits, then a2 and the weight w.
  logic [Reads*CoefBits-1:0] coef_fields0, coef1;  // at multiplier 11, beside psi1 (read r in field r)
  logic [Reads*NumBanks-1:0] bank_fields1, bank_rom; // at the ROM 12 read (read r in field r)
  logic [Channels*CBits-1:0]     c_mul13;   // at multiplier 13 (channel ch in field ch)
  logic [Channels*(CBits+2)-1:0] c3_mul13;  // 3 C (the radix-4 digits of multiplier 13)
  logic [TagBits-1:0]  tag_out;      // at the output register

  if (Blend) begin : gen_blend_fields
    // Decoder 10's second bank: the next one, the last bank itself for the last.
    logic [NumBanks-1:0] bank2;
    assign bank2 = (bank1 << 1) | (bank1 & (NumBanks'(1) << (NumBanks - 1)));
    assign coef_fields0 = {coef0[WeightBits +: CoefBits], coef0[CoefWord-1 -: CoefBits]};
    assign bank_fields1 = {bank2, bank1};
  end else begin : gen_single_fields
    assign coef_fields0 = coef0;
    assign bank_fields1 = bank1;
  end

  specular_delay #(.Width (Reads * CoefBits), .Depth (1), .Reset (1'b0)) u_coef_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (coef_fields0), .q_o (coef1));
  specular_delay #(.Width (Reads * NumBanks), .Depth (Mul11Stages)) u_bank_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (bank_fields1), .q_o (bank_rom));
  for (genvar ch = 0; ch < Channels; ch++) begin : gen_c_line
    specular_delay #(.Width (2 * CBits + 2), .Depth (AccStages - 1 + Mul11Stages + Rom12Stages + BlendStages)) u_c_line (
      .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv),
      .d_i ({c30[ch*(CBits+2) +: CBits+2], c0[ch*CBits +: CBits]}),
      .q_o ({c3_mul13[ch*(CBits+2) +: CBits+2], c_mul13[ch*CBits +: CBits]}));
  end
  specular_delay #(.Width (TagBits), .Depth (PipeDepth - 1)) u_tag_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (tag0), .q_o (tag_out));

  // ---------------------------------------------------------------------------------
  // Multiplier 11, ROM 12, multiplier 13
  // ---------------------------------------------------------------------------------
  logic [Reads*CosAddrBits-1:0] cos_addr;
  logic [Reads*CosFracBits-1:0] cos_frac;
  logic [Reads-1:0]             zero_addr, zero_cosk;
  logic [Reads*(CosDataBits+1)-1:0] cosk;

  // One multiplier 11 per read (the blend's second forms a2 |psi|), on the same psi.
  for (genvar r = 0; r < Reads; r++) begin : gen_mul11
    specular_angle_mul #(
      .AccBits     (AccBits),
      .AngleFrac   (AngleFrac),
      .CoefBits    (CoefBits),
      .CoefFrac    (CoefFrac),
      .PsiMulFrac  (PsiMulFrac),
      .CosInterp   (CosInterp),
      .CosAddrBits (CosAddrBits),
      .CosFracBits (CosFracBits),
      .MulTileBits (MulTileBits)
    ) u_mul11 (
      .clk_i     (clk_i),
      .rst_ni    (rst_ni),
      .en_i      (adv),
      .psi_i     (psi1),
      .coef_i    (coef1[r*CoefBits +: CoefBits]),
      .n_valid_i (n_valid1),
      .addr_o    (cos_addr[r*CosAddrBits +: CosAddrBits]),
      .frac_o    (cos_frac[r*CosFracBits +: CosFracBits]),
      .zero_o    (zero_addr[r])
    );
  end

  specular_cos_k_rom #(
    .NumBanks     (NumBanks),
    .CosAddrBits  (CosAddrBits),
    .CosDataBits  (CosDataBits),
    .CosInterp    (CosInterp),
    .CosDeltaBits (CosDeltaBits),
    .CosFracBits  (CosFracBits),
    .CosRomFile   (CosRomFile),
    .MulTileBits  (MulTileBits),
    .Reads        (Reads)
  ) u_cos_k_rom12 (
    .clk_i  (clk_i),
    .en_i   (adv),
    .bank_i (bank_rom),
    .addr_i (cos_addr),
    .frac_i (cos_frac),
    .cosk_o (cosk)
  );

  // The zero flags travel alongside ROM 12; a bubble is a zero pixel too, so
  // px_intensity_o reads 0 whenever px_valid_o is low.
  specular_delay #(.Width (Reads), .Depth (Rom12Stages)) u_zero_line (
    .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (zero_addr), .q_o (zero_cosk));

  // Into multiplier 13: the read itself, or the blend of both.
  logic [CosDataBits:0] cos_mul13;
  logic                 zero_mul13, valid_mul13;
  assign valid_mul13 = stage_valid[AccStages - 1 + Mul11Stages + Rom12Stages + BlendStages];

  if (Blend) begin : gen_blend
    logic valid_rom;   // the pixel at the blend's input
    assign valid_rom = stage_valid[AccStages - 1 + Mul11Stages + Rom12Stages];
    // The weight w of the second read, beside the pixel from ROM 9 to the blend.
    logic [WeightBits-1:0] w_blend;
    specular_delay #(.Width (WeightBits), .Depth (AccStages - 1 + Mul11Stages + Rom12Stages), .Reset (1'b0)) u_w_line (
      .clk_i (clk_i), .rst_ni (rst_ni), .en_i (adv), .d_i (coef0[WeightBits-1:0]), .q_o (w_blend));

    specular_blend #(
      .CosDataBits (CosDataBits),
      .WeightBits  (WeightBits),
      .MulTileBits (MulTileBits)
    ) u_blend (
      .clk_i   (clk_i),
      .en_i    (adv),
      .c1_i    (cosk[0 +: CosDataBits + 1]),
      .c2_i    (cosk[CosDataBits + 1 +: CosDataBits + 1]),
      .zero1_i (zero_cosk[0] | ~valid_rom),   // a bubble's reads are 0 (its pixel is 0 anyway)
      .zero2_i (zero_cosk[1] | ~valid_rom),
      .w_i     (w_blend),
      .cosb_o  (cos_mul13)
    );
    // Each read's zero flag is applied in the blend: a pixel is 0 when both reads are.
    assign zero_mul13 = ~valid_mul13;
  end else begin : gen_single
    assign cos_mul13  = cosk;
    assign zero_mul13 = zero_cosk[0] | ~valid_mul13;
  end

  // One multiplier 13 per channel, side by side on the pixel's one cos^k.
  logic [Channels*CBits-1:0] intensity;

  for (genvar ch = 0; ch < Channels; ch++) begin : gen_mul13
    specular_intensity_mul #(
      .CBits       (CBits),
      .CosDataBits (CosDataBits),
      .MulTileBits (MulTileBits)
    ) u_mul13 (
      .clk_i       (clk_i),
      .rst_ni      (rst_ni),
      .en_i        (adv),
      .c_i         (c_mul13[ch*CBits +: CBits]),
      .c3_i        (c3_mul13[ch*(CBits+2) +: CBits+2]),
      .cosk_i      (cos_mul13),
      .zero_i      (zero_mul13),
      .intensity_o (intensity[ch*CBits +: CBits])
    );
  end

  // ---------------------------------------------------------------------------------
  // Output buffer: the pixel handshake; its registered room is the pipeline advance
  // ---------------------------------------------------------------------------------
  logic unused_adv_d;
  specular_out_buf #(
    .Width (Channels * CBits + 1 + TagBits)
  ) u_out_buf (
    .clk_i      (clk_i),
    .rst_ni     (rst_ni),
    .adv_o      (adv),
    .adv_d_o    (unused_adv_d),  // the advance is adv_o itself here
    .in_valid_i (out_valid),
    .in_data_i  ({intensity, out_last, tag_out}),
    .px_valid_o (px_valid_o),
    .px_ready_i (px_ready_i),
    .px_data_o  ({px_intensity_o, px_last_o, px_tag_o})
  );

  // ---------------------------------------------------------------------------------
  // Assertions (rtl/prim/specular_assert.svh). The blocks check their own invariants (the
  // output buffer: valid held and the pixel stable while stalled, 0 while invalid); these
  // are the ones that span blocks: every pixel belongs to an accepted span. The formal
  // proof of the handshake is rtl/core/formal/specular_stream_fv.sv.
  // ---------------------------------------------------------------------------------
  // Inputs: the handshake bits are never X; a span offered and a pixel sent are known.
  `SPEC_ASSERT_KNOWN(SpanValidKnown_A, span_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(SpanCKnown_A, {span_c_i, span_n_i, span_len_i}, span_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(SpanPsiKnown_A, {span_psi0_i, span_dpsi_i}, span_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(SpanTagKnown_A, span_tag_i, span_valid_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(PxReadyKnown_A, px_ready_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(PxKnown_A, {px_intensity_o, px_last_o, px_tag_o}, px_valid_o, clk_i, rst_ni)

`ifndef SYNTHESIS
  // Pixels owed: l + 1 per accepted span, minus one per transfer. Wide enough for every
  // span that fits in the pipeline.
  localparam int OweBits = LenBits + 4;
  logic [OweBits-1:0] owed_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      owed_q <= '0;
    end else begin
      owed_q <= owed_q
                + (accept ? OweBits'(span_len_i) + OweBits'(1) : '0)
                - ((px_valid_o && px_ready_i) ? OweBits'(1) : '0);
    end
  end

  // No pixel without an accepted span; the last pixel owed is marked last; nothing in
  // flight when nothing is owed.
  `SPEC_ASSERT_IF(PxOwed_A, px_valid_o, owed_q != '0, clk_i, rst_ni)
  `SPEC_ASSERT_IF(LastOwedIsLast_A, px_valid_o && owed_q == OweBits'(1), px_last_o, clk_i, rst_ni)
  `SPEC_ASSERT_IF(NoneOwedEmpty_A, owed_q == '0, stage_valid == '0, clk_i, rst_ni)
`endif

endmodule
