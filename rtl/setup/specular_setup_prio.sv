// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_setup_prio: the most significant set bit of a_i, as its index (FromTop = 0) or as
// the count of zeros above it (FromTop = 1): a binary tree, clog2(W) levels of 2:1
// multiplexers, node l holding l bits (its upper half's count when that half has a set bit,
// else the lower half's with the top bit set). A priority loop over the bits ("if (a[b]) v =
// b") maps to a chain of W multiplexers, which was the critical path of the setup after
// place and route (docs/setup_hw.md#the-rtl). The input is zero-padded to a power of two
// at the top (FromTop = 0: the index is the count's complement) or at the bottom (FromTop = 1).
// Combinational; any_o low (a_i = 0) leaves value_o undefined for the caller to replace.

module specular_setup_prio #(
  parameter int W       = 8,     // a_i's bits
  parameter bit FromTop = 1'b0,
  localparam int L      = (W > 1) ? $clog2(W) : 1
) (
  input  logic [W-1:0] a_i,
  output logic         any_o,
  output logic [L-1:0] value_o
);

  localparam int LN = 1 << L;  // the tree's leaves

  logic [LN-1:0] lead;
  if (FromTop) begin : gen_pad_bottom
    if (LN > W) begin : gen_pad
      assign lead = {a_i, (LN - W)'(0)};
    end else begin : gen_full
      assign lead = a_i;
    end
  end else begin : gen_pad_top
    assign lead = LN'(a_i);
  end

  // Node n of level l covers leaves n 2^l .. (n + 1) 2^l - 1 counted from the top: any_t[l LN + n]
  // (a set bit) and its zeros above it, lz_t[(l LN + n) L +: L] (l bits used); flat, as Yosys
  // 0.23 reads no multidimensional packed arrays.
  logic [(L+1)*LN-1:0]   any_t;
  logic [(L+1)*LN*L-1:0] lz_t;
  always_comb begin
    any_t = '0;
    lz_t  = '0;
    for (int n = 0; n < LN; n++) begin
      any_t[n] = lead[LN-1-n];
    end
    // (Constant loop bounds and a guard: Icarus 11 reads no variable bound in always_comb.)
    for (int l = 1; l <= L; l++) begin
      for (int n = 0; n < LN / 2; n++) begin
        if (n < (LN >> l)) begin
          any_t[l*LN + n] = any_t[(l-1)*LN + 2*n] | any_t[(l-1)*LN + 2*n + 1];
          lz_t[(l*LN + n)*L +: L] = any_t[(l-1)*LN + 2*n] ? lz_t[((l-1)*LN + 2*n)*L +: L]
                                    : lz_t[((l-1)*LN + 2*n + 1)*L +: L] | L'(1 << (l - 1));
        end
      end
    end
  end
  assign any_o   = any_t[L*LN];
  assign value_o = FromTop ? lz_t[L*LN*L +: L] : ~lz_t[L*LN*L +: L];

endmodule
