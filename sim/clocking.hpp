// SPDX-License-Identifier: Apache-2.0
// Clocking and reset of a Verilator model, shared by the regression (sim/) and the RTL block
// tests (tests/rtl/rtl_harness.hpp).
//
// Cycle convention: in "cycle c" the caller sets the inputs, calls eval() and reads the outputs
// (the state after the edge that ended cycle c-1, plus the combinational response to the
// inputs), then tick() applies the rising edge that ends cycle c.
#pragma once

namespace specular::sim {

template <class Model>
void tick(Model& m) {
  m.clk_i = 0;
  m.eval();
  m.clk_i = 1;
  m.eval();
  m.clk_i = 0;
  m.eval();
}

// Asynchronous reset (takes effect without a clock edge), held over one edge, then released.
template <class Model>
void reset(Model& m) {
  m.clk_i = 0;
  m.rst_ni = 1;
  m.eval();
  m.rst_ni = 0;
  m.eval();
  tick(m);
  m.rst_ni = 1;
  m.eval();
}

}  // namespace specular::sim
