// SPDX-License-Identifier: Apache-2.0
//
// The geometry span interface (docs/interfaces.md#geometry-span-interface), written once:
// the ports of specular_setup, specular_system and phong_stream, of the formal harnesses of
// the setup and of phong_stream, and their maps in every instance of those modules. A
// module that uses these macros names its widths VecBits (one vector component), NBits,
// LenBits, CBits (the scale is a C value) and TagBits.
//
//   `SPECULAR_GEO_PORTS          the port declarations, geo_valid_i .. geo_tag_i; no comma
//                                at either end, so the module adds its own ports after `,`
//   `SPECULAR_GEO_MAP(P, I, O)   the named connections of those ports to the signals
//                                P``valid``I, P``ready``O, P``n1``I, ...: an instance in a
//                                module with the same ports maps them through with
//                                `SPECULAR_GEO_PORT_MAP (= (geo_, _i, _o)); a harness with
//                                local signals geo_valid, geo_n1, ... uses (geo_, , )
//   `SPECULAR_GEO_DATA(P, I)     the payload, {n1, n2, h1, he, n, len, scale, tag} in this
//                                order (the tag last), as one concatenation
//   `SPECULAR_GEO_DATA_BITS      its width
// Vectors are {z, y, x}, VecBits each, signed (docs/interfaces.md#geometry-span-interface).

`ifndef SPECULAR_GEO_PORTS_SVH
`define SPECULAR_GEO_PORTS_SVH

`define SPECULAR_GEO_PORTS \
  input  logic                 geo_valid_i, \
  output logic                 geo_ready_o, \
  input  logic [3*VecBits-1:0] geo_n1_i, \
  input  logic [3*VecBits-1:0] geo_n2_i, \
  input  logic [3*VecBits-1:0] geo_h1_i, \
  input  logic [3*VecBits-1:0] geo_he_i, \
  input  logic [NBits-1:0]     geo_n_i, \
  input  logic [LenBits-1:0]   geo_len_i, \
  input  logic [CBits-1:0]     geo_scale_i, \
  input  logic [TagBits-1:0]   geo_tag_i

`define SPECULAR_GEO_MAP(P, I, O) \
  .geo_valid_i (P``valid``I), \
  .geo_ready_o (P``ready``O), \
  .geo_n1_i    (P``n1``I), \
  .geo_n2_i    (P``n2``I), \
  .geo_h1_i    (P``h1``I), \
  .geo_he_i    (P``he``I), \
  .geo_n_i     (P``n``I), \
  .geo_len_i   (P``len``I), \
  .geo_scale_i (P``scale``I), \
  .geo_tag_i   (P``tag``I)

`define SPECULAR_GEO_PORT_MAP `SPECULAR_GEO_MAP(geo_, _i, _o)

`define SPECULAR_GEO_DATA(P, I) \
  {P``n1``I, P``n2``I, P``h1``I, P``he``I, P``n``I, P``len``I, P``scale``I, P``tag``I}

`define SPECULAR_GEO_DATA_BITS (12 * VecBits + NBits + LenBits + CBits + TagBits)

`endif  // SPECULAR_GEO_PORTS_SVH
