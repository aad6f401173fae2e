// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_prio: the value of the most significant set bit of a_i, from a table of one
// value per bit (values_i, constants at the caller): the leading one's position, a shift
// amount, the constants a normalizer derives from it. A binary tree of 2:1 multiplexers,
// clog2(W) deep, each node taking its upper half's value when that half has a set bit: a
// priority loop over the bits ("if (a[b]) v = value(b)") maps to a chain of W multiplexers,
// which was the critical path of the lean setup after place and route
// (docs/setup_hw.md#the-lean-rtl). Combinational; any_o low (a_i = 0) leaves value_o
// undefined for the caller to replace.

module specular_setup_prio #(
  parameter int W  = 8,   // a_i's bits
  parameter int VW = 8    // a value's bits
) (
  input  logic [W-1:0]    a_i,
  input  logic [W*VW-1:0] values_i,  // bit b's value at [b*VW +: VW]
  output logic            any_o,
  output logic [VW-1:0]   value_o
);

  localparam int L  = (W > 1) ? $clog2(W) : 1;  // the tree's levels
  localparam int LN = 1 << L;                   // its leaves: a_i's bits, zero-padded

  // Node n of level l covers bits n 2^l .. (n + 1) 2^l - 1: any_t[l LN + n] (a set bit) and
  // val_t[(l LN + n) VW +: VW]; flat, as Yosys 0.23 reads no multidimensional packed arrays.
  logic [(L+1)*LN-1:0]    any_t;
  logic [(L+1)*LN*VW-1:0] val_t;
  always_comb begin
    any_t = '0;
    val_t = '0;
    for (int n = 0; n < W; n++) begin
      any_t[n]           = a_i[n];
      val_t[n*VW +: VW]  = values_i[n*VW +: VW];
    end
    for (int l = 1; l <= L; l++) begin
      for (int n = 0; n < (LN >> l); n++) begin
        any_t[l*LN + n] = any_t[(l-1)*LN + 2*n] | any_t[(l-1)*LN + 2*n + 1];
        val_t[(l*LN + n)*VW +: VW] = any_t[(l-1)*LN + 2*n + 1] ? val_t[((l-1)*LN + 2*n + 1)*VW +: VW]
                                                               : val_t[((l-1)*LN + 2*n)*VW +: VW];
      end
    end
  end
  assign any_o   = any_t[L*LN];
  assign value_o = val_t[L*LN*VW +: VW];

endmodule
