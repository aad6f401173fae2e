// SPDX-License-Identifier: Apache-2.0
#include "decoder_table.hpp"

#include "evaluators.hpp"
#include "metrics.hpp"

#include <algorithm>
#include <stdexcept>

namespace specular {

std::vector<int> derive_bank_max_n(const std::vector<int>& banks, const CoefSpec& spec) {
  if (banks.empty()) throw std::invalid_argument("derive_bank_max_n: empty bank set");
  for (size_t j = 0; j < banks.size(); ++j)
    if (banks[j] < 1 || (j > 0 && banks[j] <= banks[j - 1]))
      throw std::invalid_argument("derive_bank_max_n: banks must be >= 1 and strictly increasing");
  auto err = [&](int n, int k) { return max_rel_epicenter(ShapeFn(CoskEval(k, coefficient(n, k, spec))), n); };
  std::vector<int> max_n;
  int n = 1;
  for (size_t j = 0; j + 1 < banks.size(); ++j) {
    const int k0 = banks[j], k1 = banks[j + 1];
    n = std::max(n, k0);
    while (n < k1 && err(n, k1) > err(n, k0)) ++n;
    max_n.push_back(std::max(n - 1, k0));
    n = max_n.back() + 1;
  }
  max_n.push_back(kMaxN);
  return max_n;
}

}  // namespace specular
