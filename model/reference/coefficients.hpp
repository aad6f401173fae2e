// SPDX-License-Identifier: Apache-2.0
// Decoder table (patent block 10) and the coefficient policies of ROM 9, docs/device.md.
//
// The device approximates cos^n(x) by cos^k(a x). The decoder picks k from n; the
// coefficient policy picks a:
//   maclaurin  a = sqrt(n/k)          (the patent: equal x^2 terms of the two series)
//   minimax    the a minimizing the max relative epicenter error (docs/metrics.md),
//              solved numerically and deterministically, converged to 1e-9 relative
//   kutlog:Q   a = acos(Q^(1/k)) / acos(Q^(1/n))   (the 2023 paper: exact at level Q)
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace specular {

// The patent's range of the specular exponent: n in 1..kMaxN (docs/device.md, the blocks and
// the errata). Every bound on n in the model, and device::Format::max_n(), is this one.
inline constexpr int kMaxN = 1000;

// The patent's decoder table (block 10, docs/device.md): bank j has k = kPatentBanks[j] and
// serves kPatentBankMaxN[j-1] < n <= kPatentBankMaxN[j], i.e. 1 | 2 | 3..6 | 7..1000.
// device::Format::patent() takes its bank set and decoder from here.
inline constexpr std::array<int, 4> kPatentBanks{1, 2, 4, 16};
inline constexpr std::array<int, 4> kPatentBankMaxN{1, 2, 6, kMaxN};
static_assert(kPatentBankMaxN.back() == kMaxN, "the last bank ends at kMaxN");

// The decoder rule for a table `bank_max_n` (strictly increasing): the bank j with
// bank_max_n[j-1] < n <= bank_max_n[j]; -1 for n < 1, n above the last entry or NaN.
inline int decoder_bank(std::span<const int> bank_max_n, double n) {
  if (!(n >= 1.0)) return -1;
  for (std::size_t j = 0; j < bank_max_n.size(); ++j)
    if (n <= bank_max_n[j]) return static_cast<int>(j);
  return -1;
}

// The patent's table: n=1 -> 1, 2 -> 2, 3..6 -> 4, 7..1000 -> 16; 0 for n < 1 or n > kMaxN.
// (Erratum: n up to 1000 needs 10 decoder inputs; the patent draws 9.)
int decoder_k(int n);
// Same table for a real exponent: bank j serves kPatentBankMaxN[j-1] < n <= kPatentBankMaxN[j].
int decoder_k_real(double n);
// The first and the last n of each bank of the patent's table, increasing, each once:
// 1, 2, 3, 6, 7, 1000 (the exponents where the decoder switches banks, and the range's ends).
std::vector<int> patent_bank_edges();

enum class CoefPolicy { maclaurin, minimax, kutlog };

struct CoefSpec {
  CoefPolicy policy = CoefPolicy::maclaurin;
  double Q = 0.5;  // kutlog only: the level in (0, 1) where cos^k(a x) equals cos^n(x)
};

// The a of cos^k(a x) for exponent n >= 1 and bank k >= 1.
// Throws std::invalid_argument for n < 1, k < 1, or (kutlog) Q outside (0, 1).
double coefficient(double n, int k, const CoefSpec& spec);

double coef_maclaurin(double n, int k);
double coef_kutlog(double n, int k, double Q);
double coef_minimax(double n, int k);

// "maclaurin", "minimax", "kutlog:0.3" (and "kutlog", meaning Q = 0.5).
// Throws std::invalid_argument with a message naming the accepted forms.
CoefSpec parse_coef_spec(const std::string& text);
std::string to_string(const CoefSpec& spec);

}  // namespace specular
