// SPDX-License-Identifier: Apache-2.0
// Copyright (c) the specular_device authors.
//
// Input register with write enable: blocks 1 (C), 2 (dpsi), 3 (psi0) and 4 (n) of
// patent UA 71489. Data inputs 15/17/19/21, write strobes 16/18/20/22.
//
// The write enable arriving here is already qualified by the control unit (block 14):
// writes while the device is busy are dropped before they reach the register, so the
// register is stable for the whole line.

`include "specular_assert.svh"

module specular_reg #(
  parameter int Width = 16
) (
  input  logic             clk_i,
  input  logic             rst_ni,   // asynchronous, active low (patent input 25)
  input  logic             we_i,     // write strobe (16/18/20/22), qualified by "idle"
  input  logic [Width-1:0] d_i,      // data input (15/17/19/21)
  output logic [Width-1:0] q_o
);

  if (Width < 1) begin : gen_width_check
    `SPEC_PARAM_ERROR("specular_reg: Width must be >= 1")
  end

  logic [Width-1:0] q_d, q_q;

  assign q_d = we_i ? d_i : q_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      q_q <= '0;
    end else begin
      q_q <= q_d;
    end
  end

  assign q_o = q_q;

  // Assertions (rtl/prim/specular_assert.svh): the write strobe is never X, a written value is
  // known (an X would sit in the register for the whole line).
  `SPEC_ASSERT_KNOWN(WeKnown_A, we_i, clk_i, rst_ni)
  `SPEC_ASSERT_KNOWN_IF(DataKnown_A, d_i, we_i, clk_i, rst_ni)

endmodule
