// SPDX-License-Identifier: Apache-2.0
// The batched scanline setup kernel, compiled twice: by setup_batch.cpp for the x86-64
// baseline and by setup_batch_avx2.cpp with -mavx2 -mfma. Each includes this file inside its
// own namespace (SETUP_KERNEL_NS), so the two instantiations never merge at link time.
//
// The mathematics is that of scanline_setup (model/reference/scanline_setup.cpp), rearranged
// so that one pass of straight-line double arithmetic serves every ordinary span
// (docs/scanline_setup.md#batched-setup):
//   * He is not normalized: the rotated H2 is normalized instead (only its direction counts);
//   * with c = H1 x H2: gamma = atan2(|c|, H1.H2), and (c x H1) / |c| is the unit u of step 3,
//     so lambda = atan2((c x H1).N1, |c| cos t1) needs no division by |c|;
//   * C = scale * 2^(n/2 log2(A^2)) from A^2 = cos^2 t1 + (N1.u)^2, by the polynomials of
//     setup_polys.hpp; atan by a polynomial on [0, 1] after the usual octant reduction.
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
using detail::KernelFormat;

// Adding and subtracting 1.5 * 2^52 rounds |x| < 2^51 to the nearest integer (ties to even)
// with plain SSE2 arithmetic (no roundpd), so the baseline build vectorizes too.
constexpr double kRoundMagic = 6755399441055744.0;

template <int N>
inline double horner(const double (&q)[N], double u) {
  double r = q[0];
  for (int i = 1; i < N; ++i) r = r * u + q[i];
  return r;
}

// atan(x) for x in [0, 1].
inline double atan_unit(double x) { return x * horner(poly::kAtanRatio, 2.0 * x * x - 1.0); }

// atan2(y, x) for any finite y, x (atan2(0, 0) = 0), branch-free.
inline double atan2_poly(double y, double x) {
  constexpr double kPi = 3.14159265358979323846, kHalfPi = kPi / 2;
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double mn = ax < ay ? ax : ay, mx = ax < ay ? ay : ax;
  const double r = mn / (mx > 0.0 ? mx : 1.0);
  double a = atan_unit(r);
  a = ay > ax ? kHalfPi - a : a;
  a = x < 0.0 ? kPi - a : a;
  return std::copysign(a, y);
}

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
  const double u = (2.0 * m - kSqrtHalf - kSqrt2) / (kSqrt2 - kSqrtHalf);
  return e + (m - 1.0) * horner(poly::kLog2Ratio, u);
}

// 2^x for x in [-1000, 1000].
inline double exp2_poly(double x) {
  const double k = (x + kRoundMagic) - kRoundMagic;
  const double f = x - k;  // [-1/2, 1/2], exact
  // 2^k from its exponent bits: k + 1023 as an integer in the low mantissa bits of 2^52.
  const uint64_t kb = std::bit_cast<uint64_t>(k + (4503599627370496.0 + 1023.0)) & 0x7ffULL;
  return horner(poly::kExp2, 2.0 * f) * std::bit_cast<double>(kb << 52);
}

// Round half away from zero, as std::round (device::quantize_* use it), for |x| <= 2^50;
// larger magnitudes come back as +-2^50, beyond every register range.
inline double round_away(double x) {
  double a = std::fabs(x);
  a = a < 0x1p50 ? a : 0x1p50;
  const double r = (a + kRoundMagic) - kRoundMagic;
  return std::copysign(a - r >= 0.5 ? r + 1.0 : r, x);  // a - r is exact; 0.5: a tie taken to even
}

// Spans [0, count) of the arrays (count <= the block size of the caller).
inline void setup_block(const double* __restrict n1x, const double* __restrict n1y, const double* __restrict n1z,
                        const double* __restrict n2x, const double* __restrict n2y, const double* __restrict n2z,
                        const double* __restrict h1x, const double* __restrict h1y, const double* __restrict h1z,
                        const double* __restrict hex, const double* __restrict hey, const double* __restrict hez,
                        const double* __restrict nexp, const double* __restrict scale, const double* __restrict len,
                        int count, const KernelFormat& kf, const BlockOut& o) {
  // Below the scalar setup's noise floor of the chord |H2 - H1| (16 ulp) gamma is 0.
  constexpr double kChordNoise = 16.0 * 2.220446049250313e-16;
  // Vectors whose squared length lies outside this range go to the scalar setup (it tests
  // zero length and overflow on the length itself).
  constexpr double kTiny = 1e-200, kHuge = 1e200;
  // Margins around the scalar setup's own thresholds (1 + c <= 1e-30, |H2 + H1| <= 1e-12),
  // wide enough that rounding here cannot decide differently from the scalar setup.
  constexpr double kOpcSpecial = 1e-20, kHsSpecial = 1e-20;
  // Locals, so that the stores below cannot alias the format (which blocks vectorization).
  const double c_scale = kf.c_scale, c_top = kf.c_top, angle_scale = kf.angle_scale;
  const double angle_lo = kf.angle_lo, angle_hi = kf.angle_hi, max_len = kf.max_len;
  double* __restrict oc = o.c;
  double* __restrict op = o.psi0;
  double* __restrict od = o.dpsi;
  double* __restrict on = o.n;
  double* __restrict ofl = o.flags;
  double* __restrict osp = o.special;
  // Every array is distinct (the caller's block buffers and the batch's inputs).
#pragma GCC ivdep
  for (int i = 0; i < count; ++i) {
    const double nn = nexp[i], sc = scale[i], l = len[i];
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
    ordinary = nn <= 1000.0 ? ordinary : 0.0;
    ordinary = l >= 0.0 ? ordinary : 0.0;
    ordinary = l <= max_len ? ordinary : 0.0;
    ordinary = sc >= 0.0 ? ordinary : 0.0;
    ordinary = sc - sc == 0.0 ? ordinary : 0.0;  // finite

    // Unit N1, N2, H1.
    const double r1 = 1.0 / std::sqrt(d_n1), r2 = 1.0 / std::sqrt(d_n2), rh = 1.0 / std::sqrt(d_h1);
    const double ax = n1x[i] * r1, ay = n1y[i] * r1, az = n1z[i] * r1;
    const double bx = n2x[i] * r2, by = n2y[i] * r2, bz = n2z[i] * r2;
    const double hx = h1x[i] * rh, hy = h1y[i] * rh, hz = h1z[i] * rh;

    // 1. H2 = rotation of He taking N2 to N1 (Rodrigues, scanline_setup's stable form).
    const double sx = ax + bx, sy = ay + by, sz = az + bz;
    const double opc = 0.5 * (sx * sx + sy * sy + sz * sz);
    const double vx = ay * sz - az * sy, vy = az * sx - ax * sz, vz = ax * sy - ay * sx;
    const double ex = hex[i], ey = hey[i], ez = hez[i];
    const double wx = vy * ez - vz * ey, wy = vz * ex - vx * ez, wz = vx * ey - vy * ex;  // v x He
    const double ro = 1.0 / (opc > kOpcSpecial ? opc : 1.0);
    const double gx = ex - wx + (vy * wz - vz * wy) * ro;
    const double gy = ey - wy + (vz * wx - vx * wz) * ro;
    const double gz = ez - wz + (vx * wy - vy * wx) * ro;
    const double rg = 1.0 / std::sqrt(gx * gx + gy * gy + gz * gz);
    const double kx = gx * rg, ky = gy * rg, kz = gz * rg;  // H2

    // 2. gamma, and the special case H2 ~ -H1.
    const double cx = hy * kz - hz * ky, cy = hz * kx - hx * kz, cz = hx * ky - hy * kx;  // c = H1 x H2
    const double sinr = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double cosr = hx * kx + hy * ky + hz * kz;
    const double px = hx + kx, py = hy + ky, pz = hz + kz;
    const double hs2 = px * px + py * py + pz * pz;  // |H1 + H2|^2, no cancellation
    const bool noise = sinr <= kChordNoise;
    const double gamma = noise ? 0.0 : atan2_poly(sinr, cosr);

    // 3. A and lambda: t = (c x H1).N1 = |c| (N1.u).
    const double cos_t1 = ax * hx + ay * hy + az * hz;
    const double ux = cy * hz - cz * hy, uy = cz * hx - cx * hz, uz = cx * hy - cy * hx;
    const double t = noise ? 0.0 : ux * ax + uy * ay + uz * az;
    const double w = noise ? 1.0 : sinr;
    const double lambda = atan2_poly(t, w * cos_t1);
    const double nu = t / w;
    const double a2 = cos_t1 * cos_t1 + nu * nu;

    // 4. Device inputs, rounded to the register codes.
    const double lg = log2_poly(a2 > 0x1p-1000 ? a2 : 0x1p-1000);
    const double x = 0.5 * nn * lg;
    const double an = exp2_poly(x > -1000.0 ? x : -1000.0);
    const double cval = sc * an;
    double cq = round_away(cval * c_scale);
    const double c_flag = cq <= c_top ? 0.0 : 1.0;  // C >= 0 always here
    cq = cq <= c_top ? cq : c_top;
    const double psi0 = -lambda + 0.0;
    const double dpsi = l > 0.0 ? gamma / (l > 0.0 ? l : 1.0) : 0.0;
    double pq = round_away(psi0 * angle_scale), dq = round_away(dpsi * angle_scale);
    double a_flag = pq < angle_lo ? 2.0 : 0.0;
    a_flag = pq > angle_hi ? 2.0 : a_flag;
    a_flag = dq < angle_lo ? 2.0 : a_flag;
    a_flag = dq > angle_hi ? 2.0 : a_flag;
    pq = pq < angle_lo ? angle_lo : pq > angle_hi ? angle_hi : pq;
    dq = dq < angle_lo ? angle_lo : dq > angle_hi ? angle_hi : dq;

    ordinary = opc > kOpcSpecial ? ordinary : 0.0;
    ordinary = hs2 > kHsSpecial ? ordinary : 0.0;
    // Special spans get 0 everywhere (never NaN: the caller converts to integers).
    const bool take = ordinary > 0.0;
    oc[i] = take ? cq : 0.0;
    op[i] = take ? pq : 0.0;
    od[i] = take ? dq : 0.0;
    on[i] = take ? round_away(nn) : 0.0;
    ofl[i] = take ? c_flag + a_flag : 0.0;
    osp[i] = 1.0 - ordinary;
  }
}

}  // namespace specular::host::SETUP_KERNEL_NS
