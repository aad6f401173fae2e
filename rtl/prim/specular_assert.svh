// SPDX-License-Identifier: Apache-2.0
//
// Assertion macros of the core (in the manner of OpenTitan's prim_assert.sv). Every block
// states its own invariants with them; the macro picks what the tool at hand supports:
//
//   SYNTHESIS defined   nothing. Yosys defines it implicitly (scripts/synth.sh,
//                       scripts/fpga.py) and scripts/formal.sh passes -DSYNTHESIS: the
//                       formal proof has its own properties (docs/formal.md).
//   __ICARUS__ defined  an immediate assertion in `always @(posedge clk)` (Icarus 11 has
//                       no concurrent assertions): checked at the same edges, on the
//                       values before the edge.
//   otherwise           concurrent SVA, `assert property (@(posedge clk) disable iff
//                       (!rst_n) ...)`; Verilator checks them with --assert (the
//                       models of sim_regression and the specular_unit block test),
//                       parses and lints them without.
//
// A failing assertion reports `[SPEC_ASSERT] <hierarchy>.<name>: <property>` and ends the
// simulation with a non-zero status: $error, which Verilator turns into a stop, and
// $fatal in the Icarus form (Icarus carries on after an $error and exits with 0).
//
// Properties are boolean expressions of the current cycle's values, so that the Icarus
// form checks the same thing as the SVA one: no sequences, no $past. A block that needs
// an earlier value keeps it in a register under `ifndef SYNTHESIS`.
// X: `SPEC_KNOWN(sig) is 1 when sig has no X or Z bit. It is always 1 in Verilator (two-state,
// where it is !$isunknown), so the *_KNOWN macros bite in Icarus (four-state) only; there it
// is (^sig) !== 1'bx, because Icarus 11's $isunknown returns 1 for known values after some
// $display calls (seen in tests/iverilog). An X antecedent in SPEC_ASSERT_IF is vacuous in
// both forms.
// rst_n is an active-low expression. A block without a reset passes 1'b1 when its
// property holds from power-up, or a simulation-only flag with an initial value, set at its
// first enabled edge, when its registers must be loaded first (power-up contents are random
// under Verilator's +verilator+rand+reset+2).
//
//   `SPEC_ASSERT(name, prop, clk, rst_n)           prop holds at every clk edge out of reset
//   `SPEC_ASSERT_IF(name, ante, cons, clk, rst_n)  ante |-> cons (same cycle)
//   `SPEC_KNOWN(sig)                              expression: sig has no X or Z bit
//   `SPEC_ASSERT_KNOWN(name, sig, clk, rst_n)      sig has no X or Z bit
//   `SPEC_ASSERT_KNOWN_IF(name, sig, en, clk, rst_n)  en |-> sig has no X or Z bit
//   `SPEC_ASSERT_I(name, prop)                     immediate assertion, procedural code only
//                                                  (e.g. after $readmemh in an initial block)
//   `SPEC_PARAM_ERROR(msg)                         inside a generate `if` on parameters:
//                                                  elaboration error ($error); Icarus 11 has
//                                                  no elaboration-time tasks: $fatal at time 0
//   `SPEC_PRIMED(name, clk, en)                    declares the flag `name`: 0 from power-up,
//                                                  1 from the first clk edge with en high; the
//                                                  rst_n of a block without a reset whose
//                                                  registers must be loaded first (simulation
//                                                  only: use it under `ifndef SYNTHESIS)
//
// Every block has `include "specular_assert.svh"` (the guard below makes repeats harmless);
// the include directory is rtl/: the `+incdir+rtl` line of rtl/specular.f, or -I rtl.

`ifndef SPECULAR_ASSERT_SVH
`define SPECULAR_ASSERT_SVH

`ifdef SYNTHESIS

`define SPEC_ASSERT(name, prop, clk, rst_n)
`define SPEC_ASSERT_IF(name, ante, cons, clk, rst_n)
`define SPEC_ASSERT_KNOWN(name, sig, clk, rst_n)
`define SPEC_ASSERT_KNOWN_IF(name, sig, en, clk, rst_n)
`define SPEC_ASSERT_I(name, prop)
`define SPEC_KNOWN(sig) (1'b1)
`define SPEC_PARAM_ERROR(msg) $error(msg);

`elsif __ICARUS__

`define SPEC_ASSERT(name, prop, clk, rst_n)                                        \
  always @(posedge (clk)) begin                                                    \
    if ((rst_n) === 1'b1) begin : name                                             \
      assert (prop) else $fatal(1, "[SPEC_ASSERT] %m: %s", `"prop`");             \
    end                                                                            \
  end
`define SPEC_ASSERT_IF(name, ante, cons, clk, rst_n)                               \
  always @(posedge (clk)) begin                                                    \
    if ((rst_n) === 1'b1 && (ante) === 1'b1) begin : name                          \
      assert (cons) else $fatal(1, "[SPEC_ASSERT] %m: %s |-> %s", `"ante`", `"cons`"); \
    end                                                                            \
  end
`define SPEC_ASSERT_KNOWN(name, sig, clk, rst_n)                                  \
  `SPEC_ASSERT(name, `SPEC_KNOWN(sig), clk, rst_n)
`define SPEC_ASSERT_KNOWN_IF(name, sig, en, clk, rst_n)                           \
  `SPEC_ASSERT_IF(name, en, `SPEC_KNOWN(sig), clk, rst_n)
`define SPEC_ASSERT_I(name, prop)                                                  \
  begin : name                                                                     \
    assert (prop) else $fatal(1, "[SPEC_ASSERT] %m: %s", `"prop`");               \
  end
`define SPEC_KNOWN(sig) ((^(sig)) !== 1'bx)
`define SPEC_PARAM_ERROR(msg) initial $fatal(1, msg);

`else

// (Verilator takes the reset of `disable iff` for a synchronous use of an asynchronous
// reset, SYNCASYNCNET; it is not one.)
`define SPEC_ASSERT(name, prop, clk, rst_n)                                        \
  /* verilator lint_off SYNCASYNCNET */                                            \
  name: assert property (@(posedge (clk)) disable iff (!(rst_n)) (prop))           \
    else $error("[SPEC_ASSERT] %m: %s", `"prop`");                                 \
  /* verilator lint_on SYNCASYNCNET */
`define SPEC_ASSERT_IF(name, ante, cons, clk, rst_n)                               \
  /* verilator lint_off SYNCASYNCNET */                                            \
  name: assert property (@(posedge (clk)) disable iff (!(rst_n)) (ante) |-> (cons)) \
    else $error("[SPEC_ASSERT] %m: %s |-> %s", `"ante`", `"cons`");                \
  /* verilator lint_on SYNCASYNCNET */
`define SPEC_ASSERT_KNOWN(name, sig, clk, rst_n)                                  \
  `SPEC_ASSERT(name, `SPEC_KNOWN(sig), clk, rst_n)
`define SPEC_ASSERT_KNOWN_IF(name, sig, en, clk, rst_n)                           \
  `SPEC_ASSERT_IF(name, en, `SPEC_KNOWN(sig), clk, rst_n)
`define SPEC_ASSERT_I(name, prop)                                                  \
  name: assert (prop) else $error("[SPEC_ASSERT] %m: %s", `"prop`");
`define SPEC_KNOWN(sig) (!$isunknown(sig))
`define SPEC_PARAM_ERROR(msg) $error(msg);

`endif

`define SPEC_PRIMED(name, clk, en) \
  logic name = 1'b0;               \
  always_ff @(posedge (clk)) begin \
    if (en) begin                  \
      name <= 1'b1;                \
    end                            \
  end

`endif  // SPECULAR_ASSERT_SVH
