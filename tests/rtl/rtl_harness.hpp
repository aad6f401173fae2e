// SPDX-License-Identifier: Apache-2.0
// The RTL block tests' clocking and reset of a Verilator model: the regression's
// (sim/clocking.hpp, its cycle convention), under the tests' namespace.
#pragma once

#include "../../sim/clocking.hpp"

namespace specular::rtl_test {

using specular::sim::reset;
using specular::sim::tick;

}  // namespace specular::rtl_test
