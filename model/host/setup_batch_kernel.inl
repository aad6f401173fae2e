// SPDX-License-Identifier: Apache-2.0
// The batched scanline setup kernel, compiled three times: by setup_batch.cpp for the x86-64
// baseline, by setup_batch_avx2.cpp with -mavx2 -mfma and by setup_batch_avx512.cpp for
// AVX-512. Each includes this file inside its own namespace (SETUP_KERNEL_NS), so the
// instantiations never merge at link time.
//
// The mathematics is that of scanline_setup (model/setup/scanline_setup.cpp), rearranged
// so that one pass of straight-line double arithmetic serves every ordinary span
// (docs/scanline_setup.md#batched-setup):
//   * He is not normalized: the rotated H2 is normalized instead (only its direction counts);
//   * with c = H1 x H2: gamma = atan2(|c|, H1.H2), and (c x H1) / |c| is the unit u of step 3,
//     so lambda = atan2((c x H1).N1, |c| cos t1) needs no division by |c|;
//   * C = scale * 2^(n/2 log2(A^2)) from A^2 = cos^2 t1 + (N1.u)^2, by the polynomials of
//     setup_polys.hpp; atan by a polynomial on [0, 1] after the usual octant reduction;
//   * spans of l <= kSingleMaxLen take everything after the geometry in float (single_tail,
//     twice the spans per instruction; docs/scanline_setup.md#single-precision-short-spans),
//     the others in double (double_tail).
// Spans the straight-line code cannot take exactly as the scalar setup does (invalid input,
// zero-length H, N1 near -N2, H2 near -H1, vectors of extreme length) are marked `special`
// and done by the scalar setup afterwards, so their status and registers are the scalar's.
// Written as a plain loop over a block that GCC vectorizes (checked with -fopt-info-vec).
#include "setup_batch_detail.hpp"
#include "setup_polys.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

namespace specular::host::SETUP_KERNEL_NS {

using detail::BlockOut;
using detail::kBlock;
using detail::KernelFormat;
using detail::kSingleMaxLen;

// Adding and subtracting 1.5 * 2^52 rounds |x| < 2^51 to the nearest integer (ties to even)
// with plain SSE2 arithmetic (no roundpd), so the baseline build vectorizes too.
constexpr double kRoundMagic = 6755399441055744.0;

// q(u) for the coefficients q[0] (highest degree) .. q[N-1] by Estrin's scheme: the terms
// of degree I .. I+M-1 are (low half) + u^(M/2) (high half), recursively. The dependency
// chain is log2(N) multiply-adds deep instead of N (Horner), and chain length is what bounds
// this kernel: its loop body is one long chain.
// Vectors within this of unit squared length are normalized by 1/|v| = 1 - e/2 + 3e^2/8
// (e = |v|^2 - 1; the next term, 5e^3/16, is below 3e-19).
constexpr double kNearUnitBound = 0x1p-20;

template <int N, int I, int M, class T>
inline T estrin_part(const T (&q)[N], const T* pw) {
  if constexpr (I >= N) {
    return T(0);
  } else if constexpr (M == 1) {
    return q[N - 1 - I];
  } else if constexpr (I + M / 2 >= N) {
    return estrin_part<N, I, M / 2>(q, pw);
  } else {
    constexpr int k = std::bit_width(static_cast<unsigned>(M / 2)) - 1;  // u^(M/2) = pw[k]
    return estrin_part<N, I, M / 2>(q, pw) + pw[k] * estrin_part<N, I + M / 2, M / 2>(q, pw);
  }
}

// In double for the double kernel, in float (float coefficients) for the single-precision one.
template <int N, class T>
inline T poly_eval(const T (&q)[N], T u) {
  constexpr int kTop = static_cast<int>(std::bit_ceil(static_cast<unsigned>(N)));
  T pw[6];  // u^1, u^2, u^4, ..., u^32
  pw[0] = u;
  for (int k = 1; k < 6; ++k) pw[k] = pw[k - 1] * pw[k - 1];
  return estrin_part<N, 0, kTop>(q, pw);
}

// atan(x) for x in [0, 1], with the polynomial Q: poly::kAtanRatio (gamma, 1.8e-12) or
// poly::kAtanRatioLow (lambda, 4.5e-10).
template <const auto& Q = poly::kAtanRatio>
inline double atan_unit(double x) { return x * poly_eval(Q, 2.0 * x * x - 1.0); }

// atan2 in two halves, so that a caller can share one division among several: the divisor
// max(|x|, |y|) (1 for x = y = 0) and, given its reciprocal, the angle.
inline double atan2_divisor(double y, double x) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double mx = ax < ay ? ay : ax;
  return mx > 0.0 ? mx : 1.0;
}
template <const auto& Q = poly::kAtanRatio>
inline double atan2_with(double y, double x, double inv_divisor) {
  constexpr double kPi = 3.14159265358979323846, kHalfPi = kPi / 2;
  const double ax = std::fabs(x), ay = std::fabs(y);
  double a = atan_unit<Q>((ax < ay ? ax : ay) * inv_divisor);
  a = ay > ax ? kHalfPi - a : a;
  a = x < 0.0 ? kPi - a : a;
  return std::copysign(a, y);
}

// atan2(y, x) for any finite y, x (atan2(0, 0) = 0), branch-free.
inline double atan2_poly(double y, double x) { return atan2_with(y, x, 1.0 / atan2_divisor(y, x)); }

// log2(v) for v >= 2^-1000 (normal doubles).
inline double log2_poly(double v) {
  constexpr double kSqrt2 = 1.41421356237309504880, kSqrtHalf = 0.70710678118654752440;
  const uint64_t bits = std::bit_cast<uint64_t>(v);
  // The mantissa scaled into [1, 2), and the unbiased exponent, exactly as a double.
  double m = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  double e = std::bit_cast<double>((bits >> 52) | 0x4330000000000000ULL) - (4503599627370496.0 + 1023.0);
  const bool hi = m > kSqrt2;
  m = hi ? 0.5 * m : m;
  e = hi ? e + 1.0 : e;
  const double u = (2.0 * m - kSqrtHalf - kSqrt2) * kSqrt2;  // 1 / (sqrt(2) - sqrt(1/2)) = sqrt(2)
  return e + (m - 1.0) * poly_eval(poly::kLog2Ratio, u);
}

// 2^x for x in [-1000, 1000].
inline double exp2_poly(double x) {
  const double k = (x + kRoundMagic) - kRoundMagic;
  const double f = x - k;  // [-1/2, 1/2], exact
  // 2^k from its exponent bits: k + 1023 as an integer in the low mantissa bits of 2^52.
  const uint64_t kb = std::bit_cast<uint64_t>(k + (4503599627370496.0 + 1023.0)) & 0x7ffULL;
  return poly_eval(poly::kExp2, 2.0 * f) * std::bit_cast<double>(kb << 52);
}

// Round half away from zero, as std::round (device::quantize_* use it), for |x| <= 2^50;
// larger magnitudes come back as +-2^50, beyond every register range.
inline double round_away(double x) {
  double a = std::fabs(x);
  a = a < 0x1p50 ? a : 0x1p50;
  const double r = (a + kRoundMagic) - kRoundMagic;
  return std::copysign(a - r >= 0.5 ? r + 1.0 : r, x);  // a - r is exact; 0.5: a tie taken to even
}

// --- single precision (docs/scanline_setup.md#single-precision-short-spans) --------------

constexpr float kRoundMagicF = 12582912.0f;  // 1.5 * 2^23
// pi and pi/2 as a float plus the float nearest the remainder, so that pi - a keeps float accuracy.
constexpr float kPiHiF = 3.14159274f, kPiLoF = -8.74227766e-8f;
constexpr float kHalfPiHiF = 1.57079637f, kHalfPiLoF = -4.37113883e-8f;

// atan2(y, x) in float for finite y, x, given 1 / max(|x|, |y|) (any value where x = y = 0,
// which gives 0), branch-free.
inline float atan2_f(float y, float x, float inv_max) {
  const float ax = std::fabs(x), ay = std::fabs(y);
  const float r = (ax < ay ? ax : ay) * inv_max;
  float a = r * poly_eval(poly::kAtanRatioF, 2.0f * r * r - 1.0f);
  a = ay > ax ? (kHalfPiHiF - a) + kHalfPiLoF : a;
  a = x < 0.0f ? (kPiHiF - a) + kPiLoF : a;
  return std::copysign(a, y);
}

// log2(a2) in float for normal a2 > 0, given s = 1 - a2 computed apart (to float's relative
// accuracy however small): where a2 lies in [sqrt(1/2), sqrt(2)) the mantissa minus one is
// -s, so log2 keeps the relative accuracy of s near a2 = 1, which C = scale A^n needs.
inline float log2_f(float a2, float s) {
  constexpr float kSqrt2 = 1.41421356f, kSqrtHalf = 0.707106781f;
  const uint32_t bits = std::bit_cast<uint32_t>(a2);
  float m = std::bit_cast<float>((bits & 0x007fffffU) | 0x3f800000U);
  float e = std::bit_cast<float>((bits >> 23) | 0x4b000000U) - (8388608.0f + 127.0f);
  const bool hi = m > kSqrt2;
  m = hi ? 0.5f * m : m;
  e = hi ? e + 1.0f : e;
  const float u = (2.0f * m - kSqrtHalf - kSqrt2) * kSqrt2;
  const float m1 = e == 0.0f ? -s : m - 1.0f;
  return e + m1 * poly_eval(poly::kLog2RatioF, u);
}

// 2^x in float for x in [-126, 126].
inline float exp2_f(float x) {
  const float k = (x + kRoundMagicF) - kRoundMagicF;
  const float f = x - k;  // [-1/2, 1/2], exact
  const uint32_t kb = std::bit_cast<uint32_t>(k + (8388608.0f + 127.0f)) & 0xffU;
  return poly_eval(poly::kExp2F, 2.0f * f) * std::bit_cast<float>(kb << 23);
}

// Round half away from zero for |x| < 2^22; above, x itself (a float there is a multiple of
// 1/2 at least: within half a code, which the error budget counts).
inline float round_away_f(float x) {
  const float a = std::fabs(x);
  const float r = (a + kRoundMagicF) - kRoundMagicF;
  const float q = a - r >= 0.5f ? r + 1.0f : r;
  return std::copysign(a < 4194304.0f ? q : a, x);
}

// The single-precision tail of short spans: stages 2 to 4 of setup_block in float from the
// double geometry of stage 1 (converted on load), rounded to codes in float and written to
// the block's (double) output. Inputs, per span: |c|^2 = |G|^2 sin^2 gamma, |G| cos gamma,
// t = |c| (N1.u), cos t1, sin^2 t1, the noise flag (w = |c|, or 1 where gamma is below the
// noise floor), n, scale, l. `special` = 1 where C lies within the float error
// of the saturation boundary: the scalar setup decides those, so the flag is the scalar's.
// Spans the caller does not take from here may hold anything (their results are ignored).
// kRegs: the register arrays `r` are written directly (the narrow single-precision format,
// angle codes in int32), instead of the block's double arrays `o`.
template <bool kRegs = false>
inline void single_tail(const double* __restrict b_c2, const double* __restrict b_cosr,
                        const double* __restrict b_t, const double* __restrict b_cos, const double* __restrict b_sin2,
                        const double* __restrict b_noise, const double* __restrict nexp,
                        const double* __restrict scale, const int32_t* __restrict len, int count, const KernelFormat& kf,
                        const BlockOut& o, const detail::RegOut* r = nullptr) {
  alignas(64) int32_t psi[kBlock], dps[kBlock], fl_st[kBlock];  // kRegs: fl_st = flags | status << 8
  uint32_t* __restrict reg_c = kRegs ? r->c : nullptr;
  uint32_t* __restrict reg_n = kRegs ? r->n : nullptr;
  uint32_t* __restrict reg_len = kRegs ? r->len : nullptr;
  double* __restrict oc = o.c;
  double* __restrict op = o.psi0;
  double* __restrict od = o.dpsi;
  double* __restrict on = o.n;
  double* __restrict ofl = o.flags;
  double* __restrict osp = o.special;
  const float c_scale = static_cast<float>(kf.c_scale), c_top = static_cast<float>(kf.c_top);
  const float angle_scale = static_cast<float>(kf.angle_scale);
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const float nz = static_cast<float>(b_noise[i]);
    const bool noise = nz != 0.0f;
    // |c| from |c|^2 here (a float square root: half the cost of stage 1's double one).
    const float sinr = std::sqrt(static_cast<float>(b_c2[i])), cosr = static_cast<float>(b_cosr[i]);
    const float t = static_cast<float>(b_t[i]), cs = static_cast<float>(b_cos[i]), sin2 = static_cast<float>(b_sin2[i]);
    const float nn = static_cast<float>(nexp[i]), sc = static_cast<float>(scale[i]);
    const float l = static_cast<float>(len[i]);
    const float w = noise ? 1.0f : sinr;
    // Two divisions: 1 / (w mg l) gives 1 / w, 1 / mg and 1 / l (the range check of the
    // caller keeps the product a normal float), then 1 / ml.
    const float as = std::fabs(sinr), ac = std::fabs(cosr);
    const float mg = as < ac ? ac : as, lden = l > 0.0f ? l : 1.0f;
    const float wm = w * mg, r3 = 1.0f / (wm * lden);
    const float rs = r3 * mg * lden, rg = r3 * w * lden, rl = r3 * wm;
    const float qu = t * rs;  // N1.u
    // lambda = atan2(t, w cos t1) = atan2(N1.u, cos t1). Below 2^-40 for both, A < 2^-40 and
    // C = 0: the clamp only keeps the reciprocal finite.
    const float aq = std::fabs(qu), acs = std::fabs(cs);
    float ml = aq < acs ? acs : aq;
    ml = ml > 0x1p-40f ? ml : 0x1p-40f;
    const float gamma = noise ? 0.0f : atan2_f(sinr, cosr, rg);
    const float lambda = atan2_f(qu, cs, 1.0f / ml);
    // A^2 = cos^2 t1 + (N1.u)^2 = 1 - s with s = sin^2 t1 - (N1.u)^2: sin^2 t1 from double,
    // and (N1.u)^2 <= sin^2 t1 so that its float error is small where s is (A near 1).
    const float s = sin2 - qu * qu;
    const float a2 = cs * cs + qu * qu;
    const float lg = log2_f(a2 > 0x1p-100f ? a2 : 0x1p-100f, s);
    const float x = 0.5f * nn * lg;
    const float v = sc * exp2_f(x > -100.0f ? x : -100.0f) * c_scale;
    float cq = round_away_f(v);
    const float c_flag = cq <= c_top ? 0.0f : 1.0f;
    cq = cq <= c_top ? cq : c_top;
    const float sp = std::fabs(v - (c_top + 0.5f)) <= 1e-4f * v + 1.0f ? 1.0f : 0.0f;
    const float pq = round_away_f(-lambda * angle_scale) + 0.0f;
    const float dq = l > 0.0f ? round_away_f(gamma * angle_scale * rl) : 0.0f;
    if constexpr (kRegs) {
      reg_c[i] = static_cast<uint32_t>(static_cast<int32_t>(cq));
      reg_n[i] = static_cast<uint32_t>(static_cast<int32_t>(round_away_f(nn)));
      reg_len[i] = static_cast<uint32_t>(len[i]);
      psi[i] = static_cast<int32_t>(pq);
      dps[i] = static_cast<int32_t>(dq);
      fl_st[i] = static_cast<int32_t>(c_flag + sp * (256.0f * detail::kSpecialStatus));
    } else {
      // Written as doubles (the driver's block format), converted here in the float loop.
      osp[i] = static_cast<double>(sp);
      oc[i] = static_cast<double>(cq);
      op[i] = static_cast<double>(pq);
      od[i] = static_cast<double>(dq);
      on[i] = static_cast<double>(round_away_f(nn));
      ofl[i] = static_cast<double>(c_flag);
    }
  }
  if constexpr (kRegs) {
    // The 64-bit and 8-bit arrays in loops of their own (mixed with the floats above they stop
    // the vectorizer).
    int64_t* __restrict reg_p = r->psi0;
    int64_t* __restrict reg_d = r->dpsi;
    uint8_t* __restrict reg_f = r->flags;
    uint8_t* __restrict reg_s = r->status;
#pragma GCC ivdep
    for (int i = 0; i < count; ++i) reg_p[i] = psi[i], reg_d[i] = dps[i];
#pragma GCC ivdep
    for (int i = 0; i < count; ++i) {
      reg_f[i] = static_cast<uint8_t>(fl_st[i] & 0xff);
      reg_s[i] = static_cast<uint8_t>(fl_st[i] >> 8);
    }
  }
}

// Block results (entry j) to the register arrays: span idx[j], or j when idx is null.
inline void block_to_regs(const BlockOut& t, const int* idx, int n, const int32_t* len, const detail::RegOut& r) {
  for (int j = 0; j < n; ++j) {
    const int i = idx ? idx[j] : j;
    r.psi0[i] = static_cast<int64_t>(t.psi0[j]);
    r.dpsi[i] = static_cast<int64_t>(t.dpsi[j]);
    r.c[i] = static_cast<uint32_t>(static_cast<int32_t>(t.c[j]));
    r.n[i] = static_cast<uint32_t>(static_cast<int32_t>(t.n[j]));
    r.len[i] = static_cast<uint32_t>(len[i]);
    r.flags[i] = static_cast<uint8_t>(static_cast<int32_t>(t.flags[j]));
    r.status[i] = t.special[j] != 0.0 ? detail::kSpecialStatus : static_cast<uint8_t>(SetupStatus::ok);
  }
}

// Stages 2 to 4 of setup_block in double (the spans the single-precision tail does not take),
// from stage 1's arrays.
inline void double_tail(const double* __restrict b_ord, const double* __restrict b_c2,
                        const double* __restrict b_cosr, const double* __restrict b_t, const double* __restrict b_cos,
                        const double* __restrict b_noise, const double* __restrict nexp,
                        const double* __restrict scale, const int32_t* __restrict len, int count, const KernelFormat& kf,
                        const BlockOut& o) {
  const double c_scale = kf.c_scale, c_top = kf.c_top, angle_scale = kf.angle_scale;
  const double angle_lo = kf.angle_lo, angle_hi = kf.angle_hi;
  double* __restrict oc = o.c;
  double* __restrict op = o.psi0;
  double* __restrict od = o.dpsi;
  double* __restrict on = o.n;
  double* __restrict ofl = o.flags;
  double* __restrict osp = o.special;
  alignas(64) double b_rl[kBlock], b_gamma[kBlock], b_lambda[kBlock], b_a2[kBlock];
  // Stage 2: lambda = atan2(t, |c| cos t1) and A^2 = cos^2 t1 + t^2 / |c|^2; one division
  // serves both atan2, 1 / |c|^2 and 1 / l. (The floor only keeps a degenerate span, A ~ 0
  // and so C = 0, finite.)
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const bool noise = b_noise[i] != 0.0;
    const double sinr = std::sqrt(b_c2[i]), cosr = b_cosr[i], t = b_t[i], cos_t1 = b_cos[i];
    const double w = noise ? 1.0 : sinr;
    const double dg = atan2_divisor(sinr, cosr), dl = atan2_divisor(t, w * cos_t1), w2 = w * w;
    const double lden = len[i] > 0 ? static_cast<double>(len[i]) : 1.0;
    const double den = dg * dl * w2;
    const double prod = den * lden;
    const double rl = 1.0 / (prod > 1e-300 ? prod : 1e-300);  // 1 / (den l)
    const double rq = rl * lden;                               // 1 / den
    b_rl[i] = rl * den;                                        // 1 / l
    b_gamma[i] = noise ? 0.0 : atan2_with(sinr, cosr, rq * dl * w2);
    b_lambda[i] = atan2_with<poly::kAtanRatioLow>(t, w * cos_t1, rq * dg * w2);
    b_a2[i] = cos_t1 * cos_t1 + t * t * (rq * dg * dl);
  }

  // 4. Device inputs, rounded to the register codes.
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = static_cast<double>(len[i]), a2 = b_a2[i];
    const double lg = log2_poly(a2 > 0x1p-1000 ? a2 : 0x1p-1000);
    const double x = 0.5 * nn * lg;
    const double an = exp2_poly(x > -1000.0 ? x : -1000.0);
    double cq = round_away(sc * an * c_scale);
    const double c_flag = cq <= c_top ? 0.0 : 1.0;  // C >= 0 always here
    cq = cq <= c_top ? cq : c_top;
    const double psi0 = -b_lambda[i] + 0.0;
    const double dpsi = l > 0.0 ? b_gamma[i] * b_rl[i] : 0.0;
    double pq = round_away(psi0 * angle_scale), dq = round_away(dpsi * angle_scale);
    double a_flag = pq < angle_lo ? 2.0 : 0.0;
    a_flag = pq > angle_hi ? 2.0 : a_flag;
    a_flag = dq < angle_lo ? 2.0 : a_flag;
    a_flag = dq > angle_hi ? 2.0 : a_flag;
    pq = pq < angle_lo ? angle_lo : pq > angle_hi ? angle_hi : pq;
    dq = dq < angle_lo ? angle_lo : dq > angle_hi ? angle_hi : dq;
    // Special spans get 0 everywhere (never NaN: the caller converts to integers).
    const double ordinary = b_ord[i];
    const bool take = ordinary > 0.0;
    oc[i] = take ? cq : 0.0;
    op[i] = take ? pq : 0.0;
    od[i] = take ? dq : 0.0;
    on[i] = take ? round_away(nn) : 0.0;
    ofl[i] = take ? c_flag + a_flag : 0.0;
    osp[i] = 1.0 - ordinary;
  }
}

// Spans [0, count) of the arrays (count <= the block size of the caller). kRegs: the results
// go to the register arrays `r` (single_tail's direct path, the driver's narrow
// single-precision format), `o` serving as scratch.
template <bool kRegs>
inline void setup_block_impl(const double* __restrict n1x, const double* __restrict n1y, const double* __restrict n1z,
                             const double* __restrict n2x, const double* __restrict n2y, const double* __restrict n2z,
                             const double* __restrict h1x, const double* __restrict h1y, const double* __restrict h1z,
                             const double* __restrict hex, const double* __restrict hey, const double* __restrict hez,
                             const double* __restrict nexp, const double* __restrict scale,
                             const int32_t* __restrict len, int count, const KernelFormat& kf, const BlockOut& o,
                             const detail::RegOut* r) {
  // Below the scalar setup's noise floor of the chord |H2 - H1| (16 ulp) gamma is 0.
  constexpr double kChordNoise = 16.0 * 2.220446049250313e-16;
  // Vectors whose squared length lies outside this range go to the scalar setup (it tests
  // zero length and overflow on the length itself); inside it no product below overflows
  // or underflows (the largest, |G|^2 |c|^4, stays within 1e+-240).
  constexpr double kTiny = 1e-60, kHuge = 1e60;
  // Margins around the scalar setup's own thresholds (1 + c <= 1e-30, |H2 + H1| <= 1e-12),
  // wide enough that rounding here cannot decide differently from the scalar setup:
  // 1 + c <= 1e-20, and sin^2 gamma <= 1e-20 with cos gamma < 0 (|H2 + H1| <~ 1e-10).
  constexpr double kOpcSpecial = 1e-20, kHsSpecial = 1e-20;
  // Locals, so that the stores below cannot alias the format (which blocks vectorization).
  const double max_len = kf.max_len;
  // The work is split into three loops over the block (geometry; the two atan2 and A^2; C and
  // the codes) with block-local arrays between them. One loop body would be one long
  // dependency chain; shorter bodies let the CPU overlap many spans (loop fission).
  alignas(64) double b_ord[kBlock], b_c2[kBlock], b_cosr[kBlock], b_t[kBlock], b_cos[kBlock];
  alignas(64) double b_noise[kBlock], b_sin2[kBlock], b_k2[kBlock], b_wide[kBlock];
  // Stage 1, the geometry. Vectors from a rasterizer are unit to rounding, and then
  // 1/sqrt(d) = 1 - e/2 + 3e^2/8 with e = d - 1 (the next term, 5e^3/16, is below 3e-19 for
  // |e| <= 2^-20) replaces three square roots and a division. kNearUnit = true assumes that
  // and returns true when some span of the block is farther from unit length; the block is
  // then done again with kNearUnit = false.
  auto stage1 = [&]<bool kNearUnit>() -> bool {
  int64_t far = 0;
  // Every array is distinct (the caller's block buffers, the batch's inputs, the locals).
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = static_cast<double>(len[i]);
    const double d_n1 = n1x[i] * n1x[i] + n1y[i] * n1y[i] + n1z[i] * n1z[i];
    const double d_n2 = n2x[i] * n2x[i] + n2y[i] * n2y[i] + n2z[i] * n2z[i];
    const double d_h1 = h1x[i] * h1x[i] + h1y[i] * h1y[i] + h1z[i] * h1z[i];
    const double d_he = hex[i] * hex[i] + hey[i] * hey[i] + hez[i] * hez[i];
    // 1.0 for a span the straight-line code takes, else 0.0. Conditions are chained as double
    // selects, not combined as bools: mixed-width masks stop GCC's vectorizer. NaN anywhere
    // makes a comparison false, so such a span is not ordinary.
    double ordinary = d_n1 >= kTiny ? 1.0 : 0.0;
    ordinary = d_n1 <= kHuge ? ordinary : 0.0;
    ordinary = d_n2 >= kTiny ? ordinary : 0.0;
    ordinary = d_n2 <= kHuge ? ordinary : 0.0;
    ordinary = d_h1 >= kTiny ? ordinary : 0.0;
    ordinary = d_h1 <= kHuge ? ordinary : 0.0;
    ordinary = d_he >= kTiny ? ordinary : 0.0;
    ordinary = d_he <= kHuge ? ordinary : 0.0;
    ordinary = nn >= 1.0 ? ordinary : 0.0;
    ordinary = nn <= kMaxN ? ordinary : 0.0;
    ordinary = l >= 0.0 ? ordinary : 0.0;
    ordinary = l <= max_len ? ordinary : 0.0;
    ordinary = sc >= 0.0 ? ordinary : 0.0;
    ordinary = sc - sc == 0.0 ? ordinary : 0.0;  // finite

    // Unit N1, N2, H1.
    double r1, r2, rh;
    if constexpr (kNearUnit) {
      const double e1 = d_n1 - 1.0, e2 = d_n2 - 1.0, e3 = d_h1 - 1.0;
      r1 = 1.0 + e1 * (-0.5 + 0.375 * e1);
      r2 = 1.0 + e2 * (-0.5 + 0.375 * e2);
      rh = 1.0 + e3 * (-0.5 + 0.375 * e3);
      far |= std::fabs(e1) > kNearUnitBound ? 1 : 0;
      far |= std::fabs(e2) > kNearUnitBound ? 1 : 0;
      far |= std::fabs(e3) > kNearUnitBound ? 1 : 0;
    } else {
      // Three square roots, one division for the three reciprocals.
      const double s1 = std::sqrt(d_n1), s2 = std::sqrt(d_n2), s3 = std::sqrt(d_h1);
      const double s12 = s1 * s2, p123 = 1.0 / (s12 * s3);
      r1 = s2 * s3 * p123, r2 = s1 * s3 * p123, rh = s12 * p123;
    }
    const double ax = n1x[i] * r1, ay = n1y[i] * r1, az = n1z[i] * r1;
    const double bx = n2x[i] * r2, by = n2y[i] * r2, bz = n2z[i] * r2;
    const double hx = h1x[i] * rh, hy = h1y[i] * rh, hz = h1z[i] * rh;

    // 1. G = (1 + c) times the rotation of He taking N2 to N1 (Rodrigues in scanline_setup's
    //    stable form, multiplied through by 1 + c > 0 to save the division). Only the
    //    direction of H2 = G / |G| counts below, so neither He nor G is normalized.
    const double sx = ax + bx, sy = ay + by, sz = az + bz;
    const double opc = 0.5 * (sx * sx + sy * sy + sz * sz);
    const double vx = ay * sz - az * sy, vy = az * sx - ax * sz, vz = ax * sy - ay * sx;
    const double ex = hex[i], ey = hey[i], ez = hez[i];
    const double wx = vy * ez - vz * ey, wy = vz * ex - vx * ez, wz = vx * ey - vy * ex;  // v x He
    const double kx = opc * (ex - wx) + (vy * wz - vz * wy);
    const double ky = opc * (ey - wy) + (vz * wx - vx * wz);
    const double kz = opc * (ez - wz) + (vx * wy - vy * wx);

    // 2. gamma = atan2(|c|, H1.G) with c = H1 x G (the scale |G| cancels).
    const double cx = hy * kz - hz * ky, cy = hz * kx - hx * kz, cz = hx * ky - hy * kx;
    const double k2 = kx * kx + ky * ky + kz * kz;
    const double c2 = cx * cx + cy * cy + cz * cz;
    const double cosr = hx * kx + hy * ky + hz * kz;  // |G| cos gamma
    // Near gamma = 0 and pi the chord |H2 -+ H1| is sin gamma to first order, so both tests
    // compare |c|^2 = |G|^2 sin^2 gamma with |G|^2 times the squared threshold.
    const bool noise = c2 <= kChordNoise * kChordNoise * k2;
    ordinary = opc > kOpcSpecial ? ordinary : 0.0;  // N1 ~ -N2
    ordinary = (cosr < 0.0) & (c2 <= kHsSpecial * k2) ? 0.0 : ordinary;  // H2 ~ -H1

    // 3. t = (c x H1).N1 = |c| (N1.u) for the unit u of docs/scanline_setup.md step 3.
    const double ux = cy * hz - cz * hy, uy = cz * hx - cx * hz, uz = cx * hy - cy * hx;
    b_ord[i] = ordinary;
    b_c2[i] = c2;  // |c|^2 = |G|^2 sin^2 gamma (the tails take the square root)
    b_cosr[i] = cosr;
    b_cos[i] = ax * hx + ay * hy + az * hz;  // cos t1
    b_t[i] = noise ? 0.0 : ux * ax + uy * ay + uz * az;
    b_noise[i] = noise ? 1.0 : 0.0;
    // For the single-precision tail: sin^2 t1 = 1 - cos^2 t1 (accurate near t1 = 0), |G|^2
    // for its range check, and whether |c|^2 is a normal float (or gamma below the noise floor).
    const double ct = b_cos[i];
    b_sin2[i] = (1.0 - ct) * (1.0 + ct);
    b_k2[i] = k2;
    b_wide[i] = noise || c2 >= 0x1p-120 ? 1.0 : 0.0;
  }
  return far != 0;
  };
  if (stage1.template operator()<true>()) stage1.template operator()<false>();


  // Which spans the single-precision tail takes: ordinary, l <= kSingleMaxLen, |G| within
  // 2^+-20 (no float overflow or underflow of the products there) and scale <= 2^20.
  alignas(64) double single[kBlock];
  const double single_len = kf.single ? static_cast<double>(kSingleMaxLen) : -1.0;
  int64_t singles = 0;
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double l = static_cast<double>(len[i]), k2 = b_k2[i];
    double el = b_ord[i];
    el = b_wide[i] > 0.0 ? el : 0.0;
    el = l <= single_len ? el : 0.0;
    el = k2 >= 0x1p-40 ? el : 0.0;
    el = k2 <= 0x1p40 ? el : 0.0;
    el = scale[i] <= 0x1p20 ? el : 0.0;
    single[i] = el;
    singles += el > 0.0 ? 1 : 0;
  }
  const int n_single = static_cast<int>(singles);
  if (n_single == 0) {
    double_tail(b_ord, b_c2, b_cosr, b_t, b_cos, b_noise, nexp, scale, len, count, kf, o);
    if constexpr (kRegs) block_to_regs(o, nullptr, count, len, *r);
    return;
  }
  single_tail<kRegs>(b_c2, b_cosr, b_t, b_cos, b_sin2, b_noise, nexp, scale, len, count, kf, o, r);
  if (n_single == count) return;
  // The others through the double tail, gathered, and their results scattered.
  alignas(64) int idx[kBlock];
  int ng = 0;  // branch-free list
  for (int i = 0; i < count; ++i) {
    idx[ng] = i;
    ng += single[i] > 0.0 ? 0 : 1;
  }
  alignas(64) double g[9][kBlock];
  alignas(64) int32_t gl[kBlock];
  for (int j = 0; j < ng; ++j) {
    const int i = idx[j];
    g[0][j] = b_ord[i], g[1][j] = b_c2[i], g[2][j] = b_cosr[i], g[3][j] = b_t[i], g[4][j] = b_cos[i];
    g[5][j] = b_noise[i], g[6][j] = nexp[i], g[7][j] = scale[i], gl[j] = len[i];
  }
  alignas(64) double tc[kBlock], tp[kBlock], td[kBlock], tn[kBlock], tfl[kBlock], tsp[kBlock];
  const BlockOut t{tc, tp, td, tn, tfl, tsp};
  // GCC 12 flags the arrays as maybe uninitialized: only their first ng entries are set, and
  // only those are read.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
  double_tail(g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7], gl, ng, kf, t);
#pragma GCC diagnostic pop
  if constexpr (kRegs) {
    block_to_regs(t, idx, ng, len, *r);
  } else {
    for (int j = 0; j < ng; ++j) {
      const int i = idx[j];
      o.c[i] = tc[j], o.psi0[i] = tp[j], o.dpsi[i] = td[j], o.n[i] = tn[j], o.flags[i] = tfl[j], o.special[i] = tsp[j];
    }
  }
}

inline void setup_block(const double* n1x, const double* n1y, const double* n1z, const double* n2x,
                        const double* n2y, const double* n2z, const double* h1x, const double* h1y,
                        const double* h1z, const double* hex, const double* hey, const double* hez,
                        const double* nexp, const double* scale, const int32_t* len, int count,
                        const KernelFormat& kf, const BlockOut& o) {
  setup_block_impl<false>(n1x, n1y, n1z, n2x, n2y, n2z, h1x, h1y, h1z, hex, hey, hez, nexp, scale, len, count, kf, o,
                          nullptr);
}

// setup_block writing the register arrays of the block itself (the driver's narrow
// single-precision format): saves the double block arrays and store_block's pass over them.
inline void setup_block_regs(const double* n1x, const double* n1y, const double* n1z, const double* n2x,
                             const double* n2y, const double* n2z, const double* h1x, const double* h1y,
                             const double* h1z, const double* hex, const double* hey, const double* hez,
                             const double* nexp, const double* scale, const int32_t* len, int count,
                             const KernelFormat& kf, const detail::RegOut& r) {
  alignas(64) double c[kBlock], psi0[kBlock], dpsi[kBlock], n[kBlock], flags[kBlock], special[kBlock];
  const BlockOut o{c, psi0, dpsi, n, flags, special};
  setup_block_impl<true>(n1x, n1y, n1z, n2x, n2y, n2z, h1x, h1y, h1z, hex, hey, hez, nexp, scale, len, count, kf, o,
                         &r);
}

// Flat spans: N1 = N2 and H1 = He exactly (every one-pixel span of a rasterizer, and flat
// shading under a light and a viewer at infinity). The scalar setup's rotation is then the
// identity and its chord below the noise floor, so gamma = 0, N1.u = 0, A = |cos t1| and
// lambda = atan2(0, cos t1): C = scale |cos t1|^n, psi0 = 0 (or -pi where cos t1 < 0),
// dpsi = 0, found here from one dot product. Vectors farther than kNearUnitBound from unit
// length, and everything setup_block would leave to the scalar setup, are special here too.
inline void flat_block_double(const double* __restrict n1x, const double* __restrict n1y, const double* __restrict n1z,
                       const double* __restrict h1x, const double* __restrict h1y, const double* __restrict h1z,
                       const double* __restrict nexp, const double* __restrict scale, const int32_t* __restrict len,
                       int count, const KernelFormat& kf, const BlockOut& o) {
  constexpr double kPi = 3.14159265358979323846;
  const double c_scale = kf.c_scale, c_top = kf.c_top, max_len = kf.max_len;
  // psi0 = -pi where cos t1 < 0, clamped like every angle code (a narrow format saturates).
  const double pi_code = round_away(-kPi * kf.angle_scale);
  const double psi_neg = pi_code < kf.angle_lo ? kf.angle_lo : pi_code;
  const double psi_neg_flag = pi_code < kf.angle_lo ? 2.0 : 0.0;
  double* __restrict oc = o.c;
  double* __restrict op = o.psi0;
  double* __restrict od = o.dpsi;
  double* __restrict on = o.n;
  double* __restrict ofl = o.flags;
  double* __restrict osp = o.special;
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = static_cast<double>(len[i]);
    const double d_n1 = n1x[i] * n1x[i] + n1y[i] * n1y[i] + n1z[i] * n1z[i];
    const double d_h1 = h1x[i] * h1x[i] + h1y[i] * h1y[i] + h1z[i] * h1z[i];
    const double e1 = d_n1 - 1.0, e3 = d_h1 - 1.0;
    double ordinary = std::fabs(e1) <= kNearUnitBound ? 1.0 : 0.0;  // NaN: not ordinary
    ordinary = std::fabs(e3) <= kNearUnitBound ? ordinary : 0.0;
    ordinary = nn >= 1.0 ? ordinary : 0.0;
    ordinary = nn <= kMaxN ? ordinary : 0.0;
    ordinary = l >= 0.0 ? ordinary : 0.0;
    ordinary = l <= max_len ? ordinary : 0.0;
    ordinary = sc >= 0.0 ? ordinary : 0.0;
    ordinary = sc - sc == 0.0 ? ordinary : 0.0;  // finite
    const double r1 = 1.0 + e1 * (-0.5 + 0.375 * e1), rh = 1.0 + e3 * (-0.5 + 0.375 * e3);
    const double cos_t1 = (n1x[i] * h1x[i] + n1y[i] * h1y[i] + n1z[i] * h1z[i]) * (r1 * rh);
    const double a2 = cos_t1 * cos_t1;
    const double x = 0.5 * nn * log2_poly(a2 > 0x1p-1000 ? a2 : 0x1p-1000);
    double cq = round_away(sc * exp2_poly(x > -1000.0 ? x : -1000.0) * c_scale);
    const double c_flag = cq <= c_top ? 0.0 : 1.0;
    cq = cq <= c_top ? cq : c_top;
    const bool take = ordinary > 0.0;
    const double pq = cos_t1 < 0.0 ? psi_neg : 0.0, pflag = cos_t1 < 0.0 ? psi_neg_flag : 0.0;
    oc[i] = take ? cq : 0.0;
    op[i] = take ? pq : 0.0;
    od[i] = 0.0;
    on[i] = take ? round_away(nn) : 0.0;
    ofl[i] = take ? c_flag + pflag : 0.0;
    osp[i] = 1.0 - ordinary;
  }
}


// Flat spans with C in float (docs/scanline_setup.md#single-precision-short-spans): psi0 and
// dpsi need no precision here (0 or -pi, and 0), and C = scale |cos t1|^n takes the float
// log2 with s = 1 - cos^2 t1 from double, as single_tail does. A C within the float error of
// the saturation boundary, or a scale above 2^20, is left to the scalar setup.
inline void flat_block_single(const double* __restrict n1x, const double* __restrict n1y,
                              const double* __restrict n1z, const double* __restrict h1x,
                              const double* __restrict h1y, const double* __restrict h1z,
                              const double* __restrict nexp, const double* __restrict scale,
                              const int32_t* __restrict len, int count, const KernelFormat& kf, const BlockOut& o) {
  constexpr double kPi = 3.14159265358979323846;
  const double max_len = kf.max_len;
  const double pi_code = round_away(-kPi * kf.angle_scale);
  const double psi_neg = pi_code < kf.angle_lo ? kf.angle_lo : pi_code;
  const double psi_neg_flag = pi_code < kf.angle_lo ? 2.0 : 0.0;
  const float c_scale = static_cast<float>(kf.c_scale), c_top = static_cast<float>(kf.c_top);
  alignas(64) double b_ord[kBlock], b_cos[kBlock], b_s[kBlock];
  alignas(64) float fc[kBlock], fsp[kBlock];
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = static_cast<double>(len[i]);
    const double d_n1 = n1x[i] * n1x[i] + n1y[i] * n1y[i] + n1z[i] * n1z[i];
    const double d_h1 = h1x[i] * h1x[i] + h1y[i] * h1y[i] + h1z[i] * h1z[i];
    const double e1 = d_n1 - 1.0, e3 = d_h1 - 1.0;
    double ordinary = std::fabs(e1) <= kNearUnitBound ? 1.0 : 0.0;  // NaN: not ordinary
    ordinary = std::fabs(e3) <= kNearUnitBound ? ordinary : 0.0;
    ordinary = nn >= 1.0 ? ordinary : 0.0;
    ordinary = nn <= kMaxN ? ordinary : 0.0;
    ordinary = l >= 0.0 ? ordinary : 0.0;
    ordinary = l <= max_len ? ordinary : 0.0;
    ordinary = sc >= 0.0 ? ordinary : 0.0;
    ordinary = sc <= 0x1p20 ? ordinary : 0.0;  // also false for NaN
    const double r1 = 1.0 + e1 * (-0.5 + 0.375 * e1), rh = 1.0 + e3 * (-0.5 + 0.375 * e3);
    const double cos_t1 = (n1x[i] * h1x[i] + n1y[i] * h1y[i] + n1z[i] * h1z[i]) * (r1 * rh);
    b_ord[i] = ordinary;
    b_cos[i] = ordinary > 0.0 ? cos_t1 : 1.0;
    b_s[i] = ordinary > 0.0 ? (1.0 - cos_t1) * (1.0 + cos_t1) : 0.0;
  }
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const float cs = static_cast<float>(b_cos[i]), sf = static_cast<float>(b_s[i]);
    const float nn = static_cast<float>(nexp[i]), sc = static_cast<float>(b_ord[i] > 0.0 ? scale[i] : 0.0);
    const float a2 = cs * cs;
    const float x = 0.5f * nn * log2_f(a2 > 0x1p-100f ? a2 : 0x1p-100f, sf);
    const float v = sc * exp2_f(x > -100.0f ? x : -100.0f) * c_scale;
    fc[i] = round_away_f(v);
    fsp[i] = std::fabs(v - (c_top + 0.5f)) <= 1e-4f * v + 1.0f ? 1.0f : 0.0f;
  }
  double* __restrict oc = o.c;
  double* __restrict op = o.psi0;
  double* __restrict od = o.dpsi;
  double* __restrict on = o.n;
  double* __restrict ofl = o.flags;
  double* __restrict osp = o.special;
  const double c_top_d = kf.c_top;
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double cq = static_cast<double>(fc[i]), cos_t1 = b_cos[i];
    const double c_flag = cq <= c_top_d ? 0.0 : 1.0;
    const double ordinary = static_cast<double>(fsp[i]) > 0.0 ? 0.0 : b_ord[i];
    const bool take = ordinary > 0.0;
    const double pq = cos_t1 < 0.0 ? psi_neg : 0.0, pflag = cos_t1 < 0.0 ? psi_neg_flag : 0.0;
    oc[i] = take ? (cq <= c_top_d ? cq : c_top_d) : 0.0;
    op[i] = take ? pq : 0.0;
    od[i] = 0.0;
    on[i] = take ? round_away(nexp[i]) : 0.0;
    ofl[i] = take ? c_flag + pflag : 0.0;
    osp[i] = 1.0 - ordinary;
  }
}

// flat_block_single writing the register arrays itself (the driver's narrow single-precision
// format: angle codes fit int32), which saves the double block arrays and store_block's pass
// over them. Special spans get status kSpecialStatus; the driver counts them.
inline void flat_block_regs(const double* __restrict n1x, const double* __restrict n1y,
                            const double* __restrict n1z, const double* __restrict h1x,
                            const double* __restrict h1y, const double* __restrict h1z,
                            const double* __restrict nexp, const double* __restrict scale,
                            const int32_t* __restrict len, int count, const KernelFormat& kf,
                            const detail::RegOut& r) {
  constexpr double kPi = 3.14159265358979323846;
  const double max_len = kf.max_len;
  const double pi_code = round_away(-kPi * kf.angle_scale);
  // An int32 code (a float would round it: -pi 2^28 needs 30 bits).
  const int64_t psi_neg = static_cast<int64_t>(pi_code < kf.angle_lo ? kf.angle_lo : pi_code);
  const float psi_neg_flag = pi_code < kf.angle_lo ? 2.0f : 0.0f;
  const float c_scale = static_cast<float>(kf.c_scale), c_top = static_cast<float>(kf.c_top);
  alignas(64) double b_ord[kBlock], b_cos[kBlock], b_s[kBlock], b_neg[kBlock];
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = static_cast<double>(len[i]);
    const double d_n1 = n1x[i] * n1x[i] + n1y[i] * n1y[i] + n1z[i] * n1z[i];
    const double d_h1 = h1x[i] * h1x[i] + h1y[i] * h1y[i] + h1z[i] * h1z[i];
    const double e1 = d_n1 - 1.0, e3 = d_h1 - 1.0;
    double ordinary = std::fabs(e1) <= kNearUnitBound ? 1.0 : 0.0;  // NaN: not ordinary
    ordinary = std::fabs(e3) <= kNearUnitBound ? ordinary : 0.0;
    ordinary = nn >= 1.0 ? ordinary : 0.0;
    ordinary = nn <= kMaxN ? ordinary : 0.0;
    ordinary = l >= 0.0 ? ordinary : 0.0;
    ordinary = l <= max_len ? ordinary : 0.0;
    ordinary = sc >= 0.0 ? ordinary : 0.0;
    ordinary = sc <= 0x1p20 ? ordinary : 0.0;  // also false for NaN
    const double r1 = 1.0 + e1 * (-0.5 + 0.375 * e1), rh = 1.0 + e3 * (-0.5 + 0.375 * e3);
    const double cos_t1 = (n1x[i] * h1x[i] + n1y[i] * h1y[i] + n1z[i] * h1z[i]) * (r1 * rh);
    b_ord[i] = ordinary;
    b_cos[i] = ordinary > 0.0 ? cos_t1 : 1.0;
    b_s[i] = ordinary > 0.0 ? (1.0 - cos_t1) * (1.0 + cos_t1) : 0.0;
    b_neg[i] = ordinary > 0.0 && cos_t1 < 0.0 ? 1.0 : 0.0;  // in double: a tiny negative is no float -0
  }
  uint32_t* __restrict oc = r.c;
  uint32_t* __restrict on = r.n;
  uint32_t* __restrict ol = r.len;
  int64_t* __restrict op = r.psi0;
  int64_t* __restrict od = r.dpsi;
  uint8_t* __restrict ofl = r.flags;
  uint8_t* __restrict ost = r.status;
  alignas(64) int32_t fl_st[kBlock], psi[kBlock];  // fl_st: flags | status << 8
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const float cs = static_cast<float>(b_cos[i]), sf = static_cast<float>(b_s[i]);
    const float nn = static_cast<float>(nexp[i]);
    const float ord = static_cast<float>(b_ord[i]);
    const float sc = ord > 0.0f ? static_cast<float>(scale[i]) : 0.0f;
    const float a2 = cs * cs;
    const float x = 0.5f * nn * log2_f(a2 > 0x1p-100f ? a2 : 0x1p-100f, sf);
    const float v = sc * exp2_f(x > -100.0f ? x : -100.0f) * c_scale;
    const float cq = round_away_f(v);
    // Within the float error of the saturation boundary: the scalar setup decides.
    const float near_top = std::fabs(v - (c_top + 0.5f)) <= 1e-4f * v + 1.0f ? 1.0f : 0.0f;
    const bool take = (near_top > 0.0f ? 0.0f : ord) > 0.0f;
    const float c_flag = cq <= c_top ? 0.0f : 1.0f;
    const float negf = static_cast<float>(b_neg[i]);  // 1: cos t1 < 0
    const float pflag = negf > 0.0f ? psi_neg_flag : 0.0f;
    oc[i] = static_cast<uint32_t>(static_cast<int32_t>(take ? (cq <= c_top ? cq : c_top) : 0.0f));
    on[i] = static_cast<uint32_t>(static_cast<int32_t>(take ? round_away_f(nn) : 0.0f));
    ol[i] = static_cast<uint32_t>(len[i]);
    psi[i] = static_cast<int32_t>(take ? negf : 0.0f);  // 1: psi0 = the code of -pi
    fl_st[i] = static_cast<int32_t>(take ? c_flag + pflag : 256.0f * detail::kSpecialStatus);
  }
  // The 64-bit and 8-bit arrays in loops of their own (mixed with the floats above they stop
  // the vectorizer).
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    op[i] = psi[i] != 0 ? psi_neg : 0;
    od[i] = 0;
  }
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    ofl[i] = static_cast<uint8_t>(fl_st[i] & 0xff);
    ost[i] = static_cast<uint8_t>(fl_st[i] >> 8);
  }
}

// The flat kernel the driver calls: C in float where the format allows it.
inline void flat_block(const double* __restrict n1x, const double* __restrict n1y, const double* __restrict n1z,
                       const double* __restrict h1x, const double* __restrict h1y, const double* __restrict h1z,
                       const double* __restrict nexp, const double* __restrict scale, const int32_t* __restrict len,
                       int count, const KernelFormat& kf, const BlockOut& o) {
  if (kf.single)
    flat_block_single(n1x, n1y, n1z, h1x, h1y, h1z, nexp, scale, len, count, kf, o);
  else
    flat_block_double(n1x, n1y, n1z, h1x, h1y, h1z, nexp, scale, len, count, kf, o);
}

}  // namespace specular::host::SETUP_KERNEL_NS
