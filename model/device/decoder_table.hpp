// SPDX-License-Identifier: Apache-2.0
// Decoder 10's table for a bank set (docs/device.md): which bank k serves which n.
#pragma once

#include "coefficients.hpp"

#include <vector>

namespace specular {

// bank_max_n for `banks` (strictly increasing k): bank j + 1 takes over from bank j at the
// first n where its device-independent error (max relative epicenter error of float
// cos^k(a x), a from `spec`) is not larger than bank j's. For {1, 2, 4, 16} with either
// policy this gives the patent's table 1 | 2 | 3..6 | 7..1000; the last bank ends at kMaxN.
// Throws std::invalid_argument for an empty or non-increasing bank set.
std::vector<int> derive_bank_max_n(const std::vector<int>& banks, const CoefSpec& spec);

}  // namespace specular
