// SPDX-License-Identifier: Apache-2.0
// The ROMs of the blended device (docs/display_exact.md): the domain of each ROM 12 bank, decoder
// 10's table in blend mode, and ROM 9's three fields {a1, a2, w} per n from the reference fit
// (model/reference/blend.hpp).
#pragma once

#include "blend.hpp"
#include "device_model.hpp"

#include <cstdint>
#include <vector>

namespace specular {

// The largest shift s in 0..8 per bank such that cos^k(pi/2 * 2^-s) <= 2^-24: bank k's table then
// covers its lobe down to far below any output LSB and past it gives 0
// (docs/display_exact.md#bank-domains). {1, 2, 4, 16} give 0; 64, 256, 1024 give 1, 2, 3.
std::vector<int> derive_bank_shift(const std::vector<int>& banks);

// Decoder 10 in blend mode: bank j serves banks[j] <= n < banks[j + 1] (n up to kMaxN), so that
// its pair (j, j + 1) brackets n; a last bank past kMaxN gets no entry (it is only ever a second
// bank). Throws std::invalid_argument unless the set starts at 1 and increases strictly.
std::vector<int> derive_blend_bank_max_n(const std::vector<int>& banks);

// A blend format: `base`'s widths with `banks`, their shifts and the blend decoder table.
device::Format blend_format(const device::Format& base, const std::vector<int>& banks);

// ROM 9's fields for every n of 1..max_n: word n of coef = round(a1 2^s1 2/pi 2^coef_frac), of
// coef2 the same for a2 and bank j + 1's shift, of weight round(t 2^weight_bits) (at most
// 2^weight_bits - 1). `table[n - 1]` is n's fit (blend_minimax_table); n past the table gets
// blend_maclaurin's coefficients (valid words, for ROM entries nothing measures). Throws
// std::invalid_argument naming n when a fit's banks differ from decoder 10's or a word does not fit.
device::BlendRoms blend_rom_fields(const device::Format& f, const std::vector<BlendCoef>& table,
                                   std::vector<uint32_t>& coef);

// ROM 9 as the RTL reads it in blend mode: one word per n of coef_word_bits() bits,
// {a1, a2, w} with a1 in the most significant bits (rtl/core/specular_stream.sv), and back.
// unpack_blend_coef throws std::invalid_argument when the image has the wrong depth.
std::vector<uint64_t> blend_coef_image(const device::Format& f, const std::vector<BlendCoef>& table);
device::BlendRoms unpack_blend_coef(const device::Format& f, const std::vector<uint64_t>& words,
                                    std::vector<uint32_t>& coef);

// The fits of a blend format's bank set for every n of 1..max_n (blend_minimax_table), computed
// once per bank set and process (about 10 s each on two cores).
const std::vector<BlendCoef>& blend_table_for(const device::Format& f);

// The golden model of a blend format with ROM 12 from cos_rom_image (the caller may pass one).
device::DeviceModel blend_device_model(const device::Format& f, const std::vector<BlendCoef>& table);
device::DeviceModel blend_device_model(const device::Format& f, const std::vector<BlendCoef>& table,
                                       std::vector<uint32_t> cos_rom);

}  // namespace specular
