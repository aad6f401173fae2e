// SPDX-License-Identifier: Apache-2.0
//
// The span descriptor interface (docs/interfaces.md#stream-interface-specular_stream),
// written once: specular_stream takes it (inputs), specular_setup produces it (outputs), the
// formal harnesses of both mirror it and specular_system joins the two. Here in prim's
// include directory because the setup, which needs no core, produces it. A module that uses
// these macros names its widths CBits, AngleBits, NBits, LenBits and TagBits.
//
//   `SPECULAR_SPAN_PORTS(In, Out, I, O)  the port declarations span_valid .. span_tag: In
//                                        and I for the descriptor's direction (input, _i at
//                                        the stream; output, _o at the setup), Out and O for
//                                        span_ready; no comma at either end
//   `SPECULAR_SPAN_MAP(I, O, P, PI, PO)  the named connections of an instance's ports
//                                        span_valid``I .. to the signals P``valid``PI, ...,
//                                        span_ready``O to P``ready``PO
//   `SPECULAR_SPAN_DATA(P, I)            the descriptor {c, psi0, dpsi, n, len, tag}

`ifndef SPECULAR_SPAN_PORTS_SVH
`define SPECULAR_SPAN_PORTS_SVH

`define SPECULAR_SPAN_PORTS(In, Out, I, O) \
  In  logic                 span_valid``I, \
  Out logic                 span_ready``O, \
  In  logic [CBits-1:0]     span_c``I, \
  In  logic [AngleBits-1:0] span_psi0``I, \
  In  logic [AngleBits-1:0] span_dpsi``I, \
  In  logic [NBits-1:0]     span_n``I, \
  In  logic [LenBits-1:0]   span_len``I, \
  In  logic [TagBits-1:0]   span_tag``I

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

`endif  // SPECULAR_SPAN_PORTS_SVH
