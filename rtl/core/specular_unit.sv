// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_unit: specular (Blinn) intensity of every pixel of a scanline, after patent
// UA 71489 ("device for determining the intensity of the specular colour component").
// Pixel i = 0..l of a line gets
//   I_i = C * cos^k(a(n) * psi_i),  psi_i = psi0 + i * dpsi,   0 where a*|psi_i| >= pi/2,
// with k and a(n) chosen per exponent n so that cos^k(a x) approximates cos^n(x).
// Bit-exact datapath contract: model/device/device_model.hpp (the golden model follows it too).
//
// Interface (docs/interfaces.md#register-interface-specular_unit; default widths):
//   clk_i                 clock; everything is synchronous to its rising edge
//   rst_ni                asynchronous reset, active low (patent input 25): all registers
//                         0, idle
//   c_we_i,    c_i[16]    write reg 1: C, unsigned, 15 fraction bits (0 <= C < 2)
//   dpsi_we_i, dpsi_i[32] write reg 2: dpsi, radians, signed, 28 fraction bits
//   psi0_we_i, psi0_i[32] write reg 3: psi0, same format
//   n_we_i,    n_i[10]    write reg 4: n, unsigned 1..1000 (0 or > 1000: all pixels 0)
//   len_we_i,  len_i[11]  write counter 5: l; the line has l + 1 pixels
//   start_i               one-cycle pulse: start the line
//   intensity_o[16]       pixel intensity, format of C (output 27); 0 while valid_o is low
//   valid_o               intensity_o holds the next pixel (data valid strobe 29)
//   busy_o                line in progress ("End", 28)
// Register values persist until rewritten (l included: this unit keeps it in u_reg5_len and
// hands it to the stream with every start).
//
// Protocol, start_i high in cycle s while idle (writes in cycle s apply to this line),
// L = specular_pkg::unit_latency (per configuration: docs/pipeline.md#stage-counts):
//   busy_o   high in cycles s+1 .. s+L+l, low in s+L+1+l, when a new start is accepted
//   valid_o  high in cycles s+L .. s+L+l, pixel i in cycle s+L+i
// i.e. latency L clocks to the first pixel, one pixel per clock, a line occupies l + L + 1
// clocks from start to the next accepted start. Writes and starts while busy are ignored.
// (For lines back to back at one pixel per clock use specular_stream directly.)
//
// Structure: the host registers 1-4 and the line length l (written while idle) and the
// patent's start latch sit in front of specular_stream, the one datapath of the core
// (control 14, counter 5, accumulator 6/7/8, ROM 9, decoder 10, multiplier 11, ROM 12,
// multiplier 13: see rtl/core/specular_stream.sv). An accepted start latches for one cycle and
// is then offered to the stream as one span, which takes it at once (the stream is empty
// whenever this unit is idle); px_ready_i is tied high. The latch cycle plus the stream's
// latency make the L clocks above.
//
// Patent errata resolved here (docs/device.md#errata-of-the-patent-and-how-each-is-resolved): n has 10 bits (the patent's decoder has 9 inputs);
// register 3 holds the unscaled -lambda and register 2 gamma/l (multiplier 11 applies
// a(n)); ROM 12 covers only [0, pi/2), so the magnitude |zeta| addresses it and
// zeta >= pi/2 outputs 0.
//
// ROM contents are read with $readmemh when the design is elaborated; the file paths are
// parameters relative to the working directory (the repository root for simulation and
// for the Yosys checks). Formats (roms/README.md): one hex word per line, no comments,
// no @ addresses.
//   CoefRomFile  2^NBits words of CoefBits bits: word n = round(a(n, k(n)) * 2/pi *
//                2^CoefFrac), 0 for n = 0 and n > 1000
//   CosRomFile   NumBanks * 2^CosAddrBits words, h = pi/2 / 2^CosAddrBits:
//                interpolated (CosInterp = 1): {v, d}, v = round(cos^k(i h) * 2^CosDataBits)
//                in CosDataBits + 1 bits, d = v - v(i + 1) in CosDeltaBits bits;
//                direct (CosInterp = 0, the patent): min(round(cos^k(i h) * 2^CosDataBits),
//                2^CosDataBits - 1) in CosDataBits bits (specular_cos_k_rom.sv)
// Parameters: the core's list (rtl/core/specular_params.svh: defaults equal struct
// specular::device::Format, the numeric ones /*verilator public*/, e.g. read as
// V<prefix>_specular_unit::CBits by a testbench that refuses to run when they differ from
// Format). The k of each ROM 12 bank (default 1, 2, 3, 4, 6, 8, 12, 16) lives only in
// CosRomFile, the hardware does not need it.

`include "specular_assert.svh"
`include "specular_params.svh"

module specular_unit #(
  `SPECULAR_CORE_PARAMS
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  input  logic                 c_we_i,
  input  logic [CBits-1:0]     c_i,
  input  logic                 dpsi_we_i,
  input  logic [AngleBits-1:0] dpsi_i,
  input  logic                 psi0_we_i,
  input  logic [AngleBits-1:0] psi0_i,
  input  logic                 n_we_i,
  input  logic [NBits-1:0]     n_i,
  input  logic                 len_we_i,
  input  logic [LenBits-1:0]   len_i,
  input  logic                 start_i,
  output logic [CBits-1:0]     intensity_o,
  output logic                 valid_o,
  output logic                 busy_o
);

  // Start in cycle s -> pixel 0 in cycle s + specular_pkg::unit_latency: the start latch
  // (specular_pkg::StartLatchStages, built here as one register) plus the stream's latency.
  if (specular_pkg::StartLatchStages != 1) begin : gen_pkg_check
    `SPEC_PARAM_ERROR("specular_unit: the start latch is one register (specular_pkg::StartLatchStages)")
  end
  // The patent's register interface has one C register (register 1): colour is the stream's.
  if (Channels != 1) begin : gen_channels_check
    `SPEC_PARAM_ERROR("specular_unit: Channels must be 1 (one C register; RGB spans: specular_stream or specular_axis)")
  end

  // ---------------------------------------------------------------------------------
  // Host registers 1-4 and the line length (inputs 15..24; writes only while idle)
  // ---------------------------------------------------------------------------------
  logic                 idle;
  logic [CBits-1:0]     c_q;
  logic [AngleBits-1:0] dpsi_q, psi0_q;
  logic [NBits-1:0]     n_q;
  logic [LenBits-1:0]   len_q;

  specular_reg #(.Width (CBits)) u_reg1_c (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (c_we_i & idle),
    .d_i    (c_i),
    .q_o    (c_q)
  );

  specular_reg #(.Width (AngleBits)) u_reg2_dpsi (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (dpsi_we_i & idle),
    .d_i    (dpsi_i),
    .q_o    (dpsi_q)
  );

  specular_reg #(.Width (AngleBits)) u_reg3_psi0 (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (psi0_we_i & idle),
    .d_i    (psi0_i),
    .q_o    (psi0_q)
  );

  specular_reg #(.Width (NBits)) u_reg4_n (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (n_we_i & idle),
    .d_i    (n_i),
    .q_o    (n_q)
  );

  // Input 23 / write 24 of counter 5: the stream's counter loads it with the span.
  specular_reg #(.Width (LenBits)) u_reg5_len (
    .clk_i  (clk_i),
    .rst_ni (rst_ni),
    .we_i   (len_we_i & idle),
    .d_i    (len_i),
    .q_o    (len_q)
  );

  // ---------------------------------------------------------------------------------
  // Control unit 14, host side: the start latch (busy, "End" 28) is set by an accepted
  // start pulse (26) and cleared when the line's last pixel is on the output; the offer
  // bit presents the registers to the stream as one span until it is taken (at once:
  // the stream is empty whenever this unit is idle).
  // ---------------------------------------------------------------------------------
  logic start_d, start_q, offer_d, offer_q;
  logic span_ready, px_last;
  logic [0:0] px_tag;

  always_comb begin
    start_d = start_q;
    offer_d = offer_q & ~span_ready;
    if (!start_q) begin
      if (start_i) begin
        start_d = 1'b1;
        offer_d = 1'b1;
      end
    end else if (valid_o && px_last) begin
      start_d = 1'b0;
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      start_q <= 1'b0;
      offer_q <= 1'b0;
    end else begin
      start_q <= start_d;
      offer_q <= offer_d;
    end
  end

  assign busy_o = start_q;
  assign idle   = ~start_q;

  specular_stream #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits     (1)
  ) u_stream (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    .span_valid_i   (offer_q),
    .span_ready_o   (span_ready),
    .span_c_i       (c_q),
    .span_psi0_i    (psi0_q),
    .span_dpsi_i    (dpsi_q),
    .span_n_i       (n_q),
    .span_len_i     (len_q),
    .span_tag_i     (1'b0),
    .px_valid_o     (valid_o),
    .px_ready_i     (1'b1),
    .px_intensity_o (intensity_o),
    .px_last_o      (px_last),
    .px_tag_o       (px_tag)
  );

  logic unused_px;
  assign unused_px = px_last ^ px_tag[0];

  // Assertions (rtl/prim/specular_assert.svh): the register interface's own contract (the
  // stream and the blocks check theirs): offer and pixels only while busy, intensity_o
  // reads 0 while valid_o is low, the host's strobes are never X.
  `SPEC_ASSERT_IF(OfferWhileBusy_A, offer_q, start_q, clk_i, rst_ni)
  `SPEC_ASSERT_IF(ValidWhileBusy_A, valid_o, start_q, clk_i, rst_ni)
  `SPEC_ASSERT_IF(IdleReadsZero_A, !valid_o, intensity_o == '0, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN(StrobesKnown_A, {c_we_i, dpsi_we_i, psi0_we_i, n_we_i, len_we_i, start_i}, clk_i, rst_ni)

endmodule
