// SPDX-License-Identifier: Apache-2.0
// The tables and shared primitives of the fixed-point scanline setup (docs/setup_hw.md): the
// log2, exp2 and 1/l tables with their polynomials, the arctangent table every CORDIC rounds
// its words from, and the input checks and decode. The setup itself is setup_fixed.hpp.
//
// Integer arithmetic only: every product is exact in 128 bits and rounded once by
// rshift_round; every table is an integer function of its address. The RTL's package
// rtl/setup/specular_setup_pkg.sv and the ROM files of roms/setup/ hold the same numbers
// (setup_romgen writes and checks them).
#pragma once

#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace specular::host::fixed {

__extension__ using i128 = __int128;
__extension__ using u128 = unsigned __int128;

// ---- The widths of the tables, each defined here once ----
inline constexpr int kLogUnitFrac = 44;    // log2_unit's argument: Q44
inline constexpr int kAtanFrac = 50;       // the arctangent table and pi: Q50
inline constexpr int kAtanIters = 48;      // its words: atan(2^-i), i < 48
inline constexpr int kGammaFrac = 30;      // gamma rounded to Q30 for the product with 1/l
inline constexpr int kLogFrac = 30;        // log2 A, n log2 A, 2^f: Q30
inline constexpr int kLogAddrBits = 10;    // log2 and exp2 table addresses
inline constexpr int kLogRecipFrac = 12;   // log2 table: reciprocal of the interval, Q12
inline constexpr int kRecipLenFrac = 31;   // 1/l table: mantissa round(2^(31 + s) / l), s = floor(log2 l)

// Round-half-up arithmetic shift right (s >= 1) or exact shift left (s <= 0).
constexpr i128 rshift_round(i128 x, int s) {
  return s <= 0 ? x * (i128{1} << -s) : (x + (i128{1} << (s - 1))) >> s;
}

// log2 of a positive Q44 value, Q30.
int64_t log2_unit(int64_t a);
// code * 2^(e / 2^30), rounded, saturated to `max_code` (e Q30; `saturated` says so).
uint32_t scale_exp2(uint32_t code, int64_t e, uint32_t max_code, bool* saturated = nullptr);

// ---- The tables (word i of each ROM) and constants, integer functions of the address ----
const std::vector<int64_t>& atan_table();         // round(atan(2^-i) 2^50), i < kAtanIters
int64_t atan_pi();                                // round(pi 2^50)
const std::vector<uint32_t>& log_recip_table();   // Q12 reciprocal of 1 + (i + 1/2)/1024
const std::vector<int64_t>& log_value_table();    // round(-log2(recip_i / 2^12) 2^30)
const std::vector<int64_t>& exp2_table();         // round(2^(i/1024) 2^30)
const std::vector<uint64_t>& recip_len_table();   // word l: round(2^(31 + s) / l), s = floor(log2 l); word 0 = 0
int recip_len_shift(uint32_t len);                // s = floor(log2 l) (0 for l = 0)
// Polynomial coefficients, Q30: log2(1+e) = e (L1 + e (L2 + e L3)), 2^f = 1 + f (E1 + f (E2 + f E3)).
struct PolyConsts {
  int64_t l1, l2, l3, e1, e2, e3;
};
const PolyConsts& poly_consts();

// The input checks of the golden model: throws std::invalid_argument, the message starting
// with `who`, unless vec_bits is in 2..24, the register formats are device::Format{}'s and every
// code fits its field.
void check_geo_span(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const char* who);
// The decisions on the codes alone: invalid_input (n = 0 or > 1000, N1 or N2 zero) or
// undefined_halfway (H1 or He zero); nothing for any other span.
std::optional<SetupStatus> decode_codes(const device::GeoSpan& g);

}  // namespace specular::host::fixed
