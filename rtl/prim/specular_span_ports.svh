// SPDX-License-Identifier: Apache-2.0
//
// The span descriptor interface (docs/interfaces.md#stream-interface-specular_stream),
// written once: specular_stream takes it (inputs), specular_setup produces it (outputs), the
// formal harnesses of both mirror it and specular_system joins the two. Here in prim's
// include directory because the setup, which needs no core, produces it. A module that uses
// these macros names its widths CBits, AngleBits, NBits, LenBits and TagBits. C and the
// intensity are Ch * CBits wide in the _CH forms (Ch values, channel 0 in the low bits: the
// core's Channels, rtl/core/specular_params.svh); the plain forms are those with Ch = 1.
//
//   `SPECULAR_SPAN_PORTS(In, Out, I, O)  the port declarations span_valid .. span_tag: In
//                                        and I for the descriptor's direction (input, _i at
//                                        the stream; output, _o at the setup), Out and O for
//                                        span_ready; no comma at either end
//   `SPECULAR_SPAN_PORTS_CH(In, Out, I, O, Ch)  the same with span_c Ch * CBits wide
//   `SPECULAR_SPAN_MAP(I, O, P, PI, PO)  the named connections of an instance's ports
//                                        span_valid``I .. to the signals P``valid``PI, ...,
//                                        span_ready``O to P``ready``PO
//   `SPECULAR_SPAN_DATA(P, I)            the descriptor {c, psi0, dpsi, n, len, tag}
//
// The pixel interface (docs/interfaces.md#stream-interface-specular_stream), the output of
// specular_stream, phong_stream and specular_system and of their harnesses:
//   `SPECULAR_PX_PORTS                   px_valid_o, px_ready_i, px_intensity_o (CBits),
//                                        px_last_o, px_tag_o; no comma at either end
//   `SPECULAR_PX_PORTS_CH(Ch)            the same with px_intensity_o Ch * CBits wide
//   `SPECULAR_PX_MAP(P, I, O)            their connections to P``valid``O, P``ready``I, ...
//   `SPECULAR_PX_PORT_MAP                the pass-through map, (px_, _i, _o)

`ifndef SPECULAR_SPAN_PORTS_SVH
`define SPECULAR_SPAN_PORTS_SVH

`define SPECULAR_SPAN_PORTS_CH(In, Out, I, O, Ch) \
  In  logic                 span_valid``I, \
  Out logic                 span_ready``O, \
  In  logic [(Ch)*CBits-1:0] span_c``I, \
  In  logic [AngleBits-1:0] span_psi0``I, \
  In  logic [AngleBits-1:0] span_dpsi``I, \
  In  logic [NBits-1:0]     span_n``I, \
  In  logic [LenBits-1:0]   span_len``I, \
  In  logic [TagBits-1:0]   span_tag``I

`define SPECULAR_SPAN_PORTS(In, Out, I, O) `SPECULAR_SPAN_PORTS_CH(In, Out, I, O, 1)

`define SPECULAR_SPAN_MAP(I, O, P, PI, PO) \
  .span_valid``I (P``valid``PI), \
  .span_ready``O (P``ready``PO), \
  .span_c``I     (P``c``PI), \
  .span_psi0``I  (P``psi0``PI), \
  .span_dpsi``I  (P``dpsi``PI), \
  .span_n``I     (P``n``PI), \
  .span_len``I   (P``len``PI), \
  .span_tag``I   (P``tag``PI)

`define SPECULAR_SPAN_DATA(P, I) {P``c``I, P``psi0``I, P``dpsi``I, P``n``I, P``len``I, P``tag``I}

`define SPECULAR_PX_PORTS_CH(Ch) \
  output logic                 px_valid_o, \
  input  logic                 px_ready_i, \
  output logic [(Ch)*CBits-1:0] px_intensity_o, \
  output logic                 px_last_o, \
  output logic [TagBits-1:0]   px_tag_o

`define SPECULAR_PX_PORTS `SPECULAR_PX_PORTS_CH(1)

`define SPECULAR_PX_MAP(P, I, O) \
  .px_valid_o     (P``valid``O), \
  .px_ready_i     (P``ready``I), \
  .px_intensity_o (P``intensity``O), \
  .px_last_o      (P``last``O), \
  .px_tag_o       (P``tag``O)

`define SPECULAR_PX_PORT_MAP `SPECULAR_PX_MAP(px_, _i, _o)

`endif  // SPECULAR_SPAN_PORTS_SVH
