// SPDX-License-Identifier: Apache-2.0
// The scanline setup in fixed point: the bit-exact golden model of the hardware setup, a
// cancellation-free formulation (docs/setup_hw.md#the-setup). It takes a span of the
// geometry span interface (device::GeoSpan) and returns the span descriptor specular_stream
// takes (device::Span) and the status its own decisions give; what it must meet is the
// contract of docs/setup_hw.md#the-contract (model/host/setup_contract.hpp checks it).
//
// Integer arithmetic only: every product is exact (128 bits) and rounded once by
// rshift_round; block normalization shifts a vector by a common power of two. The unit width F
// (Widths::frac) is a run-time value so that the width sweep of the tests runs one build; the
// hardware's is kFrac.
//
// The steps (docs/setup_hw.md#the-datapath):
//   1. decode: invalid_input (n = 0 or > 1000, zero N1 or N2), undefined_halfway (zero H1 or
//      He), from the codes.
//   2. normalize N1, N2, H1 (rsqrt: an interpolated seed and one Newton-Raphson step). He is
//      never normalized: only the direction of the rotated vector is used.
//   3. m = N1 + N2, q = m.m (exact); opposite_normals when q < 2^-12. G' = q He - 2 (He.m) m
//      (|m|^2 times the reflection of He through the bisector; G' = He for opposite normals),
//      block-normalized; G = G' - 2 (G'.N1) N1, block-normalized: a positive multiple of H2.
//   4. x = H1.G, c = H1 x G, block-normalized together; p = H1 x N1; cos t1 = N1.H1.
//      sin^2 gamma = c.c / (c.c + x^2) (Lagrange): flat when below 2^-44 with x > 0,
//      opposite_halfway when below 2^-20 with x < 0 (then c := p, the great circle through N1).
//   5. c_hat = c / |c|, |c| = c_hat.c, N1.u = c_hat . p: |N1.u| <= |p| = sin t1 whatever the
//      error of c_hat (Cauchy-Schwarz), so A <= 1 + O(2^-F) on any chord.
//   6. CORDIC vectoring, angle only: gamma = atan2(|c|, x), lambda = atan2(N1.u, cos t1).
//   7. A^2 = cos^2 t1 + (N1.u)^2 (exact); C = scale 2^((n/2) log2 A^2); psi0 = -lambda;
//      dpsi = gamma recip(l) (log2, exp2 and the 1/l table: setup_tables.hpp).
#pragma once

#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"
#include "setup_tables.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace specular::host::fixed {

// ---- The widths (docs/setup_hw.md#widths) ----
// The hardware's unit width: F = 26 uses a fifth of the setup's share of the error on random
// spans and keeps every status (docs/setup_hw.md#widths, the sweep); F = 22 fails.
inline constexpr int kFrac = 26;
inline constexpr int kSeedAddrBits = 9;   // rsqrt seed: x = m / 2^B in [1/4, 1) addressed by its top 9 bits
inline constexpr int kSeedInterpBits = 9; // the next 9 bits interpolate linearly between two words
inline constexpr int kSeedFrac = 18;      // seed words: round(2^18 / sqrt(j / 512)), j = 128..512
inline constexpr int kFlatLog2 = 44;      // flat: sin^2 gamma < 2^-44 with x > 0
inline constexpr int kOppHalfLog2 = 20;   // opposite halfway: sin^2 gamma < 2^-20 with x < 0
inline constexpr int kOppNormLog2 = 12;   // opposite normals: |N1 + N2|^2 < 2^-12 (unit N1, N2)

// Every other width derives from F. F must be even (the radicand's bit count B = F + 4 is even)
// and in 20..30 (A^2 in Q(2F) stays below 2^63).
struct Widths {
  int frac = kFrac;
  int rsqrt_in_bits() const { return frac + 4; }   // B: radicand normalized into [2^(B-2), 2^B)
  int rsqrt_frac() const { return frac + 2; }      // 1/sqrt: Q(F+2) in (1, 2]
  int block_bits() const { return frac + 2; }      // block-normalized vectors: max |component| < 2^(F+2)
  int cordic_frac() const { return frac + 3; }     // CORDIC x, y, angle: Q(F+3)
  int cordic_iters() const { return frac + 2; }    // residual angle < 2^-(F+1)
  int cordic_bits() const { return frac + 8; }     // CORDIC registers: |value| < 16 (|(x, y)| < 8 times K)
};
void check_widths(const Widths& w);  // throws std::invalid_argument naming the allowed range

using Vec = std::array<int64_t, 3>;

// ---- Primitives, exposed for the tests and the RTL's block tests ----
// 1/sqrt(m / 2^B) in Q(F+2) for m in [2^(B-2), 2^B), B = w.rsqrt_in_bits(): seed from the
// 385-word table (linear interpolation) and one Newton-Raphson step.
int64_t rsqrt(uint64_t m, const Widths& w);
// A vector of integers of any scale (< 2^62 in magnitude) scaled to unit length, Q(F); 0 stays 0.
Vec normalize(const Vec& v, const Widths& w);
// v shifted by a common power of two (rounded half up) so that max |component| lies in
// [2^(bits-1), 2^bits] (0 stays 0); returns the shift applied to the right (may be negative).
int block_normalize(std::array<i128, 3>& v, int bits);
// CORDIC vectoring, angle only: atan2(y, x) in (-pi, pi] up to the residual, Q(frac), for
// (x, y) in Q(frac) with |(x, y)| K < 2^(bits-1-frac); x, y, z kept in `bits`-bit registers.
int64_t cordic_angle(int64_t x, int64_t y, int frac, int iters, int bits);
// round(atan(2^-i) 2^frac), the Q50 table's word (atan_table) rounded half up to `frac` bits, and pi.
int64_t atan_word(int i, int frac);
int64_t pi_word(int frac);
// The seed table: word j - 128 is round(2^18 / sqrt(j / 512)) for j = 128..512.
const std::vector<uint32_t>& seed_table();

// Intermediate values of one span (the error analysis and the RTL's debugging).
struct Trace {
  Vec n1{}, n2{}, h1{};     // unit, Q(F)
  int64_t q = 0;            // |N1 + N2|^2, Q(2F)
  Vec g{};                  // G, block-normalized
  int64_t x = 0;            // H1.G, block-normalized with c
  Vec c{};                  // H1 x G (or H1 x N1 for opposite halfway), block-normalized
  Vec p{};                  // H1 x N1, Q(F)
  int64_t cos_t1 = 0, nu = 0;  // N1.H1, N1.u: Q(F)
  int64_t c_len = 0;        // |c|, the scale of x
  bool flat = false, opposite_normals = false, opposite_halfway = false;
  int64_t gamma = 0, lambda = 0;  // Q(F+3)
  int64_t a2 = 0;           // A^2, Q(2F)
  int64_t log2_a2 = 0;      // Q30
};

struct Result {
  device::Span span;
  SetupStatus status = SetupStatus::ok;
  bool c_saturated = false;
  Trace trace;
};

// The flat path (docs/setup_hw.md#the-flat-path): the spans whose pixels do not depend on N2 and
// He, one-pixel spans (l = 0) and flat spans (N1 = N2 and H1 = He as codes). Their registers
// need only cos t1: C = scale cos^n t1 (0 when cos t1 <= 0), psi0 = dpsi = 0; the status is
// the decode's (invalid_input, undefined_halfway) or ok.
bool takes_flat_path(const device::GeoSpan& g);
Result setup_fixed_flat(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f,
                       const Widths& w = {});

// The golden model. The register formats must be device::Format{}'s and vec_bits in 2..24;
// throws std::invalid_argument otherwise.
Result setup_fixed(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f,
                  const Widths& w = {});

}  // namespace specular::host::fixed
