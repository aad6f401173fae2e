// SPDX-License-Identifier: Apache-2.0
// Whole-span specular evaluators for a software rasterizer, and the competitors they are
// timed against (the speed axis of docs/speed_error.md).
//
// A span is l + 1 pixels i = 0..l of one scanline. The device method of patent UA 71489
// makes the angle psi between N and H linear along the span (docs/scanline_setup.md, spherical
// interpolation): psi_i = psi0 + i * dpsi. The intensity is C * cos^n(psi_i), approximated
// by C * cos^k(a psi_i) (zero where a|psi_i| >= pi/2).
//
//   device_span   the device method, float, vectorized; about 0.05 % worst relative
//                 epicenter error over n = 2..1000 (docs/metrics.md metric)
//   pow_cos_span  scalar double std::pow(std::cos(psi_i), n): the exact reference
//   phong_span    per-pixel (Blinn-)Phong as a renderer writes it: lerp the normal between
//                 the span ends, normalize, N.H, pow; float; scalar libm or SLEEF AVX2
//
// SIMD paths are chosen at run time: `SimdPath::automatic` takes AVX2 (+FMA) when the CPU
// has it and the portable x86-64 baseline code otherwise; the other values force one path
// (forcing avx2 on a CPU without it throws std::runtime_error).
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace specular {

enum class SimdPath {
  automatic,  // avx2 when the CPU supports AVX2 and FMA, else scalar
  scalar,     // portable code for the x86-64 baseline (GCC may still use SSE2 vectors)
  avx2,       // AVX2 + FMA code (throws std::runtime_error when the CPU lacks it)
};
bool cpu_has_avx2();                       // AVX2 and FMA, detected once
bool cpu_has_avx512();                     // AVX-512 F, DQ and VL, detected once (the batched
                                           // setup's and the scene shaders' widest variants)
SimdPath resolve(SimdPath p);              // automatic -> the path that will run
std::string to_string(SimdPath p);         // "automatic", "scalar", "avx2"

// --- the device method ------------------------------------------------------------------
//
// Per-material state: the bank k and coefficient a of cos^k(a psi) for exponent n. Build it
// once per exponent (it runs the minimax solver, about 30 us), then shade any number of
// spans with it.
//
// Bank choice: k is the largest of {1, 2, ..., 8, 12, 16, 24, 32, 48, 64} not above n, and
// a = coef_minimax(n, k) (model/reference/coefficients.hpp), the a that minimizes the max relative
// epicenter error. For integer n <= 8 (and n = 12, 16, 24, 32, 48, 64) k = n, a = 1: the
// shape is exact. The worst over n = 2..1000 of the shape error is 0.0545 % (n = 11, k = 8)
// in exact arithmetic; the float kernel adds a few 1e-6 (measured with shape_error: 0.0545 %).
// (The patent's banks {1, 2, 4, 16} give 0.185 % at best; the power-of-two banks up to 64
// give 0.381 % at n = 3.) The set is tuned for integer n: a real n just above a bank, in the
// gap 2 < n < 3, exceeds 0.1 % (measured: n = 2.5 0.254 %, n = 3.5 0.0996 %, 4.5 0.053 %). Over the lobe past the
// epicenter the absolute error of the shape is up to about 6e-3 (docs/metrics.md lobe metric).
struct DeviceSpanPlan {
  double n = 1.0;
  int k = 1;
  double a = 1.0;
};
// n in [1, 1000] (reals allowed); throws std::invalid_argument otherwise.
DeviceSpanPlan make_device_span_plan(double n);
// The plan for integer n in 1..1000 from a table built on first use (about 30 ms, thread
// safe); throws std::invalid_argument outside 1..1000.
const DeviceSpanPlan& device_span_plan(int n);

// out[i] = C * cos^k(a * psi_i) for a|psi_i| < pi/2 (so also |psi_i| < pi/2), else 0,
// psi_i = psi0 + i * dpsi, i = 0..len (len + 1 values; out must hold them).
// Float arithmetic: u_i = a psi0 + i (a dpsi) in float (one FMA), cos(u_i) by an even
// polynomial of degree 12 (Taylor; truncation below 6.5e-9 at u = pi/2), clamped to >= 0,
// then the power k by a fixed square-and-multiply chain (k = 64: 6 squarings). No table,
// no recurrence (each pixel is computed from i, so errors do not accumulate along the span),
// no branch per pixel. Any len >= 0; len < 0 writes nothing. Non-finite inputs give
// unspecified values (no trap).
void device_span(const DeviceSpanPlan& plan, double psi0, double dpsi, int len, float C, float* out,
                 SimdPath path = SimdPath::automatic);

// --- the competitors ----------------------------------------------------------------------

// out[i] = C * std::pow(std::cos(psi_i), n) in double, 0 where cos(psi_i) <= 0.
void pow_cos_span(double n, double psi0, double dpsi, int len, double C, double* out);

// Per-pixel Phong shading of the Blinn term, float:
//   N_i = n0 + t_i (n1 - n0), t_i = i / len (t = 0 when len = 0);
//   c_i = dot(N_i, h) / |N_i|  (h must be unit length; n0, n1 need not be);
//   out[i] = C * c_i^n for c_i > 0, else 0.
// scalar: std::sqrt and std::pow (libm powf); avx2: 8 pixels at a time, _mm256_sqrt_ps and
// SLEEF's Sleef_powf8_u10avx2 (1.0 ulp). SimdPath::automatic falls back to scalar when the
// CPU lacks AVX2.
using Vec3f = std::array<float, 3>;
void phong_span(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out,
                SimdPath path = SimdPath::automatic);

// The angle between N_i (as phong_span interpolates it) and h, in double: what phong_span
// shades at pixel i. For tests and the CLI.
double phong_pixel_angle(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, int len, int i);

namespace detail {
// The two compiled variants of the kernels (span_shade.cpp and span_shade_avx2.cpp).
// u_i = u0 + i du; out[i] = C cos^k(u_i) for |u_i| < cut, else 0; k from the bank set.
void device_span_scalar(int k, float u0, float du, float cut, int len, float C, float* out);
void device_span_avx2(int k, float u0, float du, float cut, int len, float C, float* out);
void phong_span_scalar(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out);
void phong_span_avx2(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out);
}  // namespace detail

}  // namespace specular
