// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// specular_prim_pkg: the stage count of the shared primitives (docs/pipeline.md#stage-counts).
// It is apart from specular_pkg (the device's stages) so that the primitives, the setup and the
// competitors elaborate without the device core; specular_pkg builds its counts on it.
// Written for Yosys 0.23 (functions return through their name, callers write
// specular_prim_pkg::f(...)).

package specular_prim_pkg;

  // Stages of specular_pipe_mul's radix-4 tree over a b_bits-wide multiplier operand: one
  // register of the selected rows, then one per level of the binary adder tree over the
  // ceil(b_bits / 2) rows.
  function automatic int pipe_mul_stages(input int b_bits);
    pipe_mul_stages = 1 + ((((b_bits + 1) / 2) > 1) ? $clog2((b_bits + 1) / 2) : 0);
  endfunction

endpackage
