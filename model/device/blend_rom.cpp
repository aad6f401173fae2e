// SPDX-License-Identifier: Apache-2.0
// ROMs of the blended device (model/device/blend_rom.hpp, docs/display_exact.md).
#include "blend_rom.hpp"

#include "coefficients.hpp"
#include "rom_image.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace specular {

std::vector<int> derive_bank_shift(const std::vector<int>& banks) {
  std::vector<int> out;
  for (int k : banks) {
    int s = 0;
    // cos^k(pi/2 2^-(s+1)) <= 2^-24 in long double: k ln cos(x) <= -24 ln 2.
    while (s < 8 && k * std::log(std::cos(std::ldexp(std::numbers::pi_v<long double> / 2.0L, -(s + 1)))) <=
                        -24.0L * std::numbers::ln2_v<long double>)
      ++s;
    out.push_back(s);
  }
  return out;
}

std::vector<int> derive_blend_bank_max_n(const std::vector<int>& banks) {
  if (banks.empty() || banks.front() != 1)
    throw std::invalid_argument("blend bank set must start at k = 1 (decoder 10 serves every n from 1)");
  std::vector<int> m;
  for (size_t j = 0; j < banks.size(); ++j) {
    if (j > 0 && banks[j] <= banks[j - 1])
      throw std::invalid_argument("blend bank set must increase strictly (k = " + std::to_string(banks[j]) + ")");
    const int hi = j + 1 < banks.size() ? banks[j + 1] - 1 : kMaxN;
    if (hi >= kMaxN) {
      m.push_back(kMaxN);
      break;
    }
    m.push_back(hi);
  }
  return m;
}

device::Format blend_format(const device::Format& base, const std::vector<int>& banks) {
  device::Format f = base;
  f.blend = true;
  f.banks = banks;
  f.bank_shift = derive_bank_shift(banks);
  f.bank_max_n = derive_blend_bank_max_n(banks);
  return f;
}

device::BlendRoms blend_rom_fields(const device::Format& f, const std::vector<BlendCoef>& table,
                                   std::vector<uint32_t>& coef) {
  const int depth = f.coef_rom_depth();
  coef.assign(depth, 0);
  device::BlendRoms b{std::vector<uint32_t>(depth, 0), std::vector<uint32_t>(depth, 0)};
  const double wmax = std::ldexp(1.0, f.weight_bits) - 1.0;
  for (int n = 1; n <= f.max_n(); ++n) {
    const int j = decoder_bank(f.bank_max_n, n);
    const int j2 = std::min(j + 1, static_cast<int>(f.banks.size()) - 1);
    const int k1 = f.banks[j], k2 = f.banks[j2];
    const BlendCoef c = n <= static_cast<int>(table.size()) ? table[n - 1] : blend_maclaurin(n, k1, k2);
    auto fail = [&](const std::string& what) {
      return std::invalid_argument("blend ROM 9 entry n = " + std::to_string(n) + " (k1 = " + std::to_string(k1) +
                                   ", k2 = " + std::to_string(k2) + "): " + what);
    };
    if (c.n != n || c.k1 != k1 || c.k2 != k2) throw fail("the fit is for other banks or another n");
    try {
      coef[n] = coef_word(std::ldexp(c.a1, f.shift_of(j)), f);
      b.coef2[n] = coef_word(std::ldexp(c.a2, f.shift_of(j2)), f);
    } catch (const std::invalid_argument& e) {
      throw fail(e.what());
    }
    b.weight[n] = static_cast<uint32_t>(std::clamp(std::round(std::ldexp(c.t, f.weight_bits)), 0.0, wmax));
  }
  return b;
}

std::vector<uint64_t> blend_coef_image(const device::Format& f, const std::vector<BlendCoef>& table) {
  std::vector<uint32_t> coef;
  const device::BlendRoms b = blend_rom_fields(f, table, coef);
  std::vector<uint64_t> img(coef.size());
  for (size_t n = 0; n < coef.size(); ++n)
    img[n] = (static_cast<uint64_t>(coef[n]) << (f.coef_bits + f.weight_bits)) |
             (static_cast<uint64_t>(b.coef2[n]) << f.weight_bits) | b.weight[n];
  return img;
}

device::BlendRoms unpack_blend_coef(const device::Format& f, const std::vector<uint64_t>& words,
                                    std::vector<uint32_t>& coef) {
  if (static_cast<int>(words.size()) != f.coef_rom_depth())
    throw std::invalid_argument("blend ROM 9 has " + std::to_string(words.size()) + " words, expected " +
                                std::to_string(f.coef_rom_depth()));
  const uint64_t cmask = (uint64_t{1} << f.coef_bits) - 1, wmask = (uint64_t{1} << f.weight_bits) - 1;
  device::BlendRoms b;
  coef.clear();
  for (uint64_t w : words) {
    coef.push_back(static_cast<uint32_t>((w >> (f.coef_bits + f.weight_bits)) & cmask));
    b.coef2.push_back(static_cast<uint32_t>((w >> f.weight_bits) & cmask));
    b.weight.push_back(static_cast<uint32_t>(w & wmask));
  }
  return b;
}

const std::vector<BlendCoef>& blend_table_for(const device::Format& f) {
  static std::mutex m;
  static std::map<std::vector<int>, std::vector<BlendCoef>> tables;
  const std::lock_guard<std::mutex> lock(m);
  auto it = tables.find(f.banks);
  if (it == tables.end()) it = tables.emplace(f.banks, blend_minimax_table(f.banks, f.max_n())).first;
  return it->second;
}

device::DeviceModel blend_device_model(const device::Format& f, const std::vector<BlendCoef>& table,
                                       std::vector<uint32_t> cos_rom) {
  std::vector<uint32_t> coef;
  device::BlendRoms b = blend_rom_fields(f, table, coef);
  return device::DeviceModel(f, std::move(coef), std::move(cos_rom), std::move(b));
}

device::DeviceModel blend_device_model(const device::Format& f, const std::vector<BlendCoef>& table) {
  return blend_device_model(f, table, cos_rom_image(f));
}

}  // namespace specular
