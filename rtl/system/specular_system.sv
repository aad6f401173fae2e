// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_system: a complete specular shading system in hardware, geometry in, pixels out
// (docs/setup_hw.md#the-system): specular_setup turns each geometry span
// (docs/interfaces.md#geometry-span-interface) into a span descriptor, specular_stream
// shades its l + 1 pixels. The pixel side is exactly specular_stream's (px_valid_o,
// px_ready_i, px_intensity_o, px_last_o, px_tag_o, same rules); the geometry side follows
// the same AXI4-Stream rules, geo_ready_o a function of registers only (specular_setup's).
//
// The setup takes a span per clock (SetupII = 1; at most one every SetupII clocks otherwise,
// docs/setup_hw.md#the-folded-setup) and the stream a
// pixel per clock, so with
// px_ready_i high and SetupII = 1 the system shades one pixel per clock, one-pixel spans back
// to back included; the setup's two-entry output buffer and the span slice hold the
// descriptors while the stream works on a long span. The setup's status is not on the pixel side: a span it resolves to C = 0 gives l + 1
// pixels of 0.
//
// Parameters: the core's list (rtl/core/specular_params.svh) with the register formats the setup
// produces (device::Format's defaults), VecBits, TagBits, SetupII, the setup's ROM files. The
// setup's multipliers take the core's MulTileBits (one
// multiplier style for the whole system: DSP tiles or LUT trees, docs/pipeline.md#multiplier-styles).

`include "specular_assert.svh"
`include "specular_params.svh"
`include "specular_geo_ports.svh"
`include "specular_span_ports.svh"

module specular_system #(
  `SPECULAR_CORE_PARAMS,
  parameter int TagBits       = 16,
  parameter int VecBits       = 18,
  parameter int SetupII       = 1,     // the setup's: at most one span every SetupII clocks
  parameter     SeedFile      = "roms/setup/rsqrt_seed.hex",
  parameter     LogRecipFile  = "roms/setup/log_recip.hex",
  parameter     LogValueFile  = "roms/setup/log_value.hex",
  parameter     Exp2File      = "roms/setup/exp2.hex",
  parameter     RecipLenFile  = "roms/setup/recip_len.hex"
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  `SPECULAR_GEO_PORTS,
  `SPECULAR_PX_PORTS
);

  // specular_setup produces the registers in the default formats (16-bit C with 15
  // fraction bits, angles of 32 bits with 28, n of 10, l of 11).
  if (CBits != 16 || CFrac != 15 || AngleBits != 32 || AngleFrac != 28 || NBits != 10 || LenBits != 11) begin : gen_fmt_check
    `SPEC_PARAM_ERROR("specular_system: the register formats must be the defaults (C 16/15, angles 32/28, n 10, l 11)")
  end
  // specular_setup checks its own SetupII (1, or from specular_setup_pkg::MinFoldII on).
  // The setup produces one C per span (geo_scale_i).
  if (Channels != 1) begin : gen_channels_check
    `SPEC_PARAM_ERROR("specular_system: Channels must be 1 (specular_setup produces one C per span)")
  end

  localparam int SpanW = CBits + 2 * AngleBits + NBits + LenBits + TagBits;

  // The setup's descriptors (_s), then the span slice's, which the stream takes.
  logic                 span_valid_s, span_ready_s, span_valid, span_ready;
  logic [CBits-1:0]     span_c_s, span_c;
  logic [AngleBits-1:0] span_psi0_s, span_dpsi_s, span_psi0, span_dpsi;
  logic [NBits-1:0]     span_n_s, span_n;
  logic [LenBits-1:0]   span_len_s, span_len;
  logic [TagBits-1:0]   span_tag_s, span_tag;
  logic [2:0]           span_status;

  specular_setup #(
    .VecBits      (VecBits),
    .TagBits      (TagBits),
    .TileBits     (MulTileBits),
    .SetupII      (SetupII),
    .SeedFile     (SeedFile),
    .LogRecipFile (LogRecipFile),
    .LogValueFile (LogValueFile),
    .Exp2File     (Exp2File),
    .RecipLenFile (RecipLenFile)
  ) u_setup (
    .clk_i         (clk_i),
    .rst_ni        (rst_ni),
    `SPECULAR_GEO_PORT_MAP,
    `SPECULAR_SPAN_MAP(_o, _i, span_, _s, _s),
    .span_status_o (span_status)
  );

  // The span slice: the stream's span_ready_o (a function of its counter and control) reaches
  // only these flip-flops, placed beside the stream, and the setup sees a registered ready.
  // Without it the accept crossed the part twice in one clock, from the stream's counter to the
  // setup's output buffer and back to the counter's load (docs/setup_hw.md#the-system). One
  // clock of latency.
  logic [SpanW-1:0] span_data;
  if (SetupII == 1) begin : gen_slice_two
    // A descriptor per clock: two entries (specular_out_buf).
    logic unused_slice_adv_d;
    specular_out_buf #(
      .Width (SpanW)
    ) u_span_slice (
      .clk_i      (clk_i),
      .rst_ni     (rst_ni),
      .adv_o      (span_ready_s),
      .adv_d_o    (unused_slice_adv_d),
      .in_valid_i (span_valid_s),
      .in_data_i  (`SPECULAR_SPAN_DATA(span_, _s)),
      .px_valid_o (span_valid),
      .px_ready_i (span_ready),
      .px_data_o  (span_data)
    );
  end else begin : gen_slice_one
    // At most a descriptor every SetupII >= 2 clocks : one entry, which takes a
    // descriptor every two clocks at most (it is free the clock after the stream takes it),
    // keeps the rate for half the flip-flops.
    logic             full_q;
    logic [SpanW-1:0] data_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        full_q <= 1'b0;
      end else if (!full_q) begin
        full_q <= span_valid_s;
      end else if (span_ready) begin
        full_q <= 1'b0;
      end
    end
    always_ff @(posedge clk_i) begin
      if (!full_q && span_valid_s) data_q <= `SPECULAR_SPAN_DATA(span_, _s);
    end
    assign span_ready_s = !full_q;
    assign span_valid   = full_q;
    assign span_data    = data_q;
  end
  assign `SPECULAR_SPAN_DATA(span_, ) = span_data;

  specular_stream #(
    `SPECULAR_CORE_PARAM_MAP,
    .TagBits (TagBits)
  ) u_stream (
    .clk_i          (clk_i),
    .rst_ni         (rst_ni),
    `SPECULAR_SPAN_MAP(_i, _o, span_, , ),
    `SPECULAR_PX_PORT_MAP
  );

  logic [2:0] unused_status;
  assign unused_status = span_status;

endmodule
