// SPDX-License-Identifier: Apache-2.0
// Small helpers shared by the RTL block tests: clocking and reset of a Verilator model.
//
// Cycle convention used by every test: in "cycle c" the test sets the inputs, calls
// eval() and reads the outputs (state after the edge that ended cycle c-1, plus the
// combinational response to the inputs), then tick() applies the rising edge that ends
// cycle c.
#pragma once

namespace specular::rtl_test {

template <class Model>
void tick(Model& m) {
  m.clk_i = 0;
  m.eval();
  m.clk_i = 1;
  m.eval();
  m.clk_i = 0;
  m.eval();
}

template <class Model>
void reset(Model& m) {
  m.clk_i = 0;
  m.rst_ni = 1;
  m.eval();
  m.rst_ni = 0;  // asynchronous: takes effect without a clock edge
  m.eval();
  tick(m);
  m.rst_ni = 1;
  m.eval();
}

}  // namespace specular::rtl_test
