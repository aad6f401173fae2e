// SPDX-License-Identifier: Apache-2.0
// Decoder 10: exhaustive over all 1024 codes of n against the patent's table
// (n = 1 -> k = 1, n = 2 -> k = 2, n = 3..6 -> k = 4, n = 7..1000 -> k = 16; the
// banks hold k = 1, 2, 4, 16 in that order; n = 0 and n > 1000 select nothing).
#include "Vdecoder.h"

#include <catch2/catch.hpp>

namespace {

// The patent's table written out by hand (independent of BankMaxN in the RTL).
int patent_k(unsigned n) {
  if (n == 1) return 1;
  if (n == 2) return 2;
  if (n >= 3 && n <= 6) return 4;
  if (n >= 7 && n <= 1000) return 16;
  return 0;  // invalid exponent
}

unsigned onehot_for_k(int k) {
  switch (k) {
    case 1: return 0b0001;
    case 2: return 0b0010;
    case 4: return 0b0100;
    case 16: return 0b1000;
    default: return 0;
  }
}

}  // namespace

TEST_CASE("decoder 10 maps every 10-bit n to the patent's bank", "[rtl][decoder]") {
  Vdecoder dut;
  int checked = 0, valid = 0;
  for (unsigned n = 0; n < 1024; ++n) {
    dut.n_i = n;
    dut.eval();
    const int k = patent_k(n);
    INFO("n = " << n);
    CHECK(static_cast<unsigned>(dut.bank_o) == onehot_for_k(k));
    CHECK(static_cast<bool>(dut.n_valid_o) == (k != 0));
    ++checked;
    valid += (k != 0);
  }
  CHECK(checked == 1024);
  CHECK(valid == 1000);
}

TEST_CASE("decoder 10 boundaries named by the spec", "[rtl][decoder]") {
  Vdecoder dut;
  // n: expected one-hot (the boundaries 2, 3, 6, 7 and the ends of the range).
  const std::pair<unsigned, unsigned> cases[] = {
      {0, 0}, {1, 0b0001}, {2, 0b0010}, {3, 0b0100}, {6, 0b0100},
      {7, 0b1000}, {1000, 0b1000}, {1001, 0}, {1023, 0}};
  for (auto [n, onehot] : cases) {
    dut.n_i = n;
    dut.eval();
    INFO("n = " << n);
    CHECK(static_cast<unsigned>(dut.bank_o) == onehot);
  }
}
