// SPDX-License-Identifier: Apache-2.0
// The scanline setup in fixed point: the bit-exact golden model of the hardware setup
// (docs/setup_hw.md). It takes a span of the geometry span interface
// (docs/interfaces.md#geometry-span-interface, device::GeoSpan) and returns the span
// descriptor specular_stream takes (device::Span: C, psi0, dpsi, n, l, tag) and the status
// the scalar setup (model/setup/scanline_setup.hpp) gives on the same input values.
//
// Integer arithmetic only: every intermediate is an integer code, every product is exact
// in 128 bits and rounded once by rshift_round, every table is an integer function of its
// address. The widths below are the datapath's; the RTL has the same numbers.
//
// The steps (docs/setup_hw.md#datapath):
//   1. decode: invalid_input (n = 0 or > 1000, zero N1 or N2) and undefined_halfway (zero H1
//      or He) from the codes; opposite_normals from the exact integer cross product.
//   2. normalize N1, N2, H1, He (rsqrt: seed table + 2 Newton-Raphson steps).
//   3. H2 = S_N1(S_m(He)), S_u(v) = v - 2 (v.u) u, m = (N1 + N2)/|N1 + N2| (two reflections
//      are the rotation taking N2 to N1); opposite normals: m is dropped, H2 = S_N1(He).
//   4. cos t1 = N1.H1, x = H1.H2, W = H2 - x H1 (W = N1 - cos t1 H1 when H2 = -H1);
//      flat (every component of H2 - H1 within kChordFloor): gamma = 0, N1.u = 0.
//   5. U = W/|W| (rsqrt again), |W| = U.W, N1.u = N1.U.
//   6. CORDIC vectoring: gamma = atan2(|W|, x); lambda and A*K from (cos t1, N1.u).
//   7. dpsi = gamma * recip(l) (table), psi0 = -lambda, C = scale * 2^(n log2 A)
//      (log2 and exp2: table + polynomial).
#pragma once

#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace specular::host::fixed {

__extension__ using i128 = __int128;
__extension__ using u128 = unsigned __int128;

// ---- The widths, each defined here once (docs/setup_hw.md#widths) ----
// The unit vectors keep Q44: with 36 fraction bits the setup still meets 0.01 % + 1 LSB on
// the tests' spans but gives another status than the scalar setup on near-opposite halfway
// codes, with 35 or fewer it exceeds the allowance (docs/setup_hw.md#error-budget, measured).
// The rest is narrowed to what the registers need.
inline constexpr int kUnitFrac = 44;                  // unit vectors and dot products: Q44 (|value| < 8)
inline constexpr int kRsqrtInBits = kUnitFrac + 2;    // normalized radicand m in [2^44, 2^46)
inline constexpr int kRsqrtFrac = kUnitFrac;          // r = 2^67 / sqrt(m) in (2^44, 2^45]: Q44 of 1/sqrt(m / 2^46)
inline constexpr int kRsqrtAddrBits = 12;             // seed address m >> 34 in [1024, 4096): 3072 words
inline constexpr int kRsqrtSeedFrac = 16;             // seed word, Q16 (17 bits)
inline constexpr int kRsqrtSteps = 2;                 // Newton-Raphson steps after the seed
inline constexpr int kCordicFrac = kUnitFrac + 6;     // CORDIC x, y and angles: Q50 (6 guard bits)
inline constexpr int kCordicIters = kUnitFrac + 4;    // vectoring iterations (residual angle < 2^-47)
inline constexpr int kGammaFrac = 30;                 // gamma rounded to Q30 for the product with 1/l
inline constexpr int kGainFrac = 30;                  // A K rounded to Q30 for the product with 1/K (Q30)
inline constexpr int kLogFrac = 30;                   // log2 A, n log2 A, 2^f: Q30
inline constexpr int kLogAddrBits = 10;               // log2 and exp2 table addresses
inline constexpr int kLogRecipFrac = 12;              // log2 table: reciprocal of the interval, Q12
inline constexpr int kRecipLenFrac = 31;              // 1/l table: mantissa round(2^(31 + s) / l), s = floor(log2 l)
inline constexpr int kChordFloor = 16;                // Q44 codes (2^-40): H2 -+ H1 below it in every component
                                                      // is gamma = 0 (flat) or gamma = pi (opposite halfway)

// Round-half-up arithmetic shift right (s >= 1) or exact shift left (s <= 0).
constexpr i128 rshift_round(i128 x, int s) {
  return s <= 0 ? x * (i128{1} << -s) : (x + (i128{1} << (s - 1))) >> s;
}

using Vec = std::array<int64_t, 3>;  // Q44 components {x, y, z}

// ---- Primitives, exposed for the tests and the RTL's block tests ----
// Reciprocal square root of a normalized radicand m in [2^44, 2^46): Q44 of 2^23 / sqrt(m).
int64_t rsqrt_norm(uint64_t m);
// A vector of any common scale (integer codes or Q44) scaled to unit length, Q44; 0 stays 0.
Vec normalize(const Vec& v);
// Sum of the exact products, rounded once: Q44.
int64_t dot(const Vec& a, const Vec& b);
// S_u(v) = v - 2 (v.u) u.
Vec reflect(const Vec& v, const Vec& u);
// CORDIC vectoring of (x, y) (Q50): angle atan2(y, x) in (-pi, pi] up to the residual, Q50,
// and the magnitude times the CORDIC gain K, Q50.
struct Polar {
  int64_t angle = 0;
  int64_t mag_k = 0;
};
Polar cordic_vectoring(int64_t x, int64_t y);
// log2 of a positive Q44 value, Q30.
int64_t log2_unit(int64_t a);
// code * 2^(e / 2^30), rounded, saturated to `max_code` (e Q30; `saturated` says so).
uint32_t scale_exp2(uint32_t code, int64_t e, uint32_t max_code, bool* saturated = nullptr);

// ---- The tables (word i of each ROM) and constants, integer functions of the address ----
const std::vector<uint32_t>& rsqrt_seed_table();  // word a - 1024 for a in [1024, 4096)
const std::vector<int64_t>& atan_table();         // round(atan(2^-i) 2^42), i < kCordicIters
int64_t cordic_inv_gain();                        // round(2^30 / K): Q30
const std::vector<uint32_t>& log_recip_table();   // Q12 reciprocal of 1 + (i + 1/2)/1024
const std::vector<int64_t>& log_value_table();    // round(-log2(recip_i / 2^12) 2^30)
const std::vector<int64_t>& exp2_table();         // round(2^(i/1024) 2^30)
const std::vector<uint64_t>& recip_len_table();   // word l: round(2^(31 + s) / l), s = floor(log2 l); word 0 = 0
int recip_len_shift(uint32_t len);                // s = floor(log2 l) (0 for l = 0)
int64_t cordic_pi();                              // round(pi 2^42)
// Polynomial coefficients, Q30: log2(1+e) = e (L1 + e (L2 + e L3)), 2^f = 1 + f (E1 + f (E2 + f E3)).
struct PolyConsts {
  int64_t l1, l2, l3, e1, e2, e3;
};
const PolyConsts& poly_consts();

// Intermediate values of one span (for debugging and for the error analysis).
struct Trace {
  std::array<Vec, 4> unit{};  // N1, N2, H1, He normalized
  Vec h2{};                   // the rotated He
  int64_t cos_t1 = 0, x = 0;  // N1.H1, H1.H2 (Q44)
  bool flat = false, opposite_normals = false, opposite_halfway = false;
  int64_t w_len = 0, nu = 0;  // |W|, N1.u (Q44)
  int64_t gamma = 0;          // Q50
  int64_t lambda = 0;         // Q50
  int64_t a = 0;              // A, Q44
  int64_t log2_a = 0;         // Q30
};

struct Result {
  device::Span span;  // C, psi0, dpsi, n, len codes and the tag
  SetupStatus status = SetupStatus::ok;
  bool c_saturated = false;  // C clamped to the top of register 1
  Trace trace;
};

// The input checks of both golden models (this and host::lean::setup_lean): throws
// std::invalid_argument, the message starting with `who`, unless vec_bits is in 2..24, the
// register formats are device::Format{}'s and every code fits its field.
void check_geo_span(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const char* who);
// The decisions on the codes alone: invalid_input (n = 0 or > 1000, N1 or N2 zero) or
// undefined_halfway (H1 or He zero); nothing for any other span.
std::optional<SetupStatus> decode_codes(const device::GeoSpan& g);

// The golden model. Requires the default interface widths' limits: vec_bits in 2..24 and the
// register formats of device::Format{} (c 16/15, angle 32/28, n 10, len 11); throws
// std::invalid_argument otherwise.
Result setup_fixed(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f);

}  // namespace specular::host::fixed
