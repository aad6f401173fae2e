// SPDX-License-Identifier: Apache-2.0
// Span evaluators (model/reference/span_shade.hpp): plans, run-time dispatch, the portable kernels
// and the scalar competitors.
#include "span_shade.hpp"

#include "coefficients.hpp"

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#define SPAN_KERNEL_NS baseline_kernels
#include "span_shade_kernel.inl"
#undef SPAN_KERNEL_NS

namespace specular {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
constexpr int kBanks[] = {1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 24, 32, 48, 64};
}  // namespace

bool cpu_has_avx2() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return has;
}

bool cpu_has_avx512() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512vl");
  }();
  return has;
}

SimdPath resolve(SimdPath p) {
  if (p == SimdPath::automatic) return cpu_has_avx2() ? SimdPath::avx2 : SimdPath::scalar;
  if (p == SimdPath::avx2 && !cpu_has_avx2()) throw std::runtime_error("SimdPath::avx2 forced but this CPU lacks AVX2/FMA");
  return p;
}

std::string to_string(SimdPath p) {
  switch (p) {
    case SimdPath::automatic: return "automatic";
    case SimdPath::scalar: return "scalar";
    case SimdPath::avx2: return "avx2";
  }
  return "?";
}

DeviceSpanPlan make_device_span_plan(double n) {
  if (!(n >= 1.0 && n <= kMaxN))
    throw std::invalid_argument("make_device_span_plan: n must be in [1, " + std::to_string(kMaxN) + "]");
  DeviceSpanPlan p;
  p.n = n;
  for (int k : kBanks)
    if (k <= n) p.k = k;
  p.a = p.k == n ? 1.0 : coef_minimax(n, p.k);
  return p;
}

const DeviceSpanPlan& device_span_plan(int n) {
  if (n < 1 || n > kMaxN) throw std::invalid_argument("device_span_plan: n must be in 1.." + std::to_string(kMaxN));
  static const std::vector<DeviceSpanPlan> table = [] {
    std::vector<DeviceSpanPlan> t;
    t.reserve(kMaxN);
    for (int m = 1; m <= kMaxN; ++m) t.push_back(make_device_span_plan(m));
    return t;
  }();
  return table[n - 1];
}

void device_span(const DeviceSpanPlan& plan, double psi0, double dpsi, int len, float C, float* out, SimdPath path) {
  if (len < 0) return;
  const float u0 = static_cast<float>(plan.a * psi0), du = static_cast<float>(plan.a * dpsi);
  // a|psi| < pi/2 and |psi| < pi/2; a >= 1 for every plan (k <= n), so the first implies
  // the second, but keep both for a hand-made plan.
  const float cut = static_cast<float>(kHalfPi * std::min(1.0, plan.a));
  if (resolve(path) == SimdPath::avx2)
    detail::device_span_avx2(plan.k, u0, du, cut, len, C, out);
  else
    detail::device_span_scalar(plan.k, u0, du, cut, len, C, out);
}

void pow_cos_span(double n, double psi0, double dpsi, int len, double C, double* out) {
  for (int i = 0; i <= len; ++i) {
    const double c = std::cos(psi0 + i * dpsi);
    out[i] = c > 0.0 ? C * std::pow(c, n) : 0.0;
  }
}

void phong_span(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out,
                SimdPath path) {
  if (resolve(path) == SimdPath::avx2)
    detail::phong_span_avx2(n0, n1, h, n, len, C, out);
  else
    detail::phong_span_scalar(n0, n1, h, n, len, C, out);
}

double phong_pixel_angle(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, int len, int i) {
  const double t = len > 0 ? static_cast<double>(i) / len : 0.0;
  double N[3], cr[3];
  for (int j = 0; j < 3; ++j) N[j] = n0[j] + t * (static_cast<double>(n1[j]) - n0[j]);
  cr[0] = N[1] * h[2] - N[2] * h[1];
  cr[1] = N[2] * h[0] - N[0] * h[2];
  cr[2] = N[0] * h[1] - N[1] * h[0];
  const double dot = N[0] * h[0] + N[1] * h[1] + N[2] * h[2];
  return std::atan2(std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), dot);
}

namespace detail {

void device_span_scalar(int k, float u0, float du, float cut, int len, float C, float* out) {
  baseline_kernels::device_dispatch(k, u0, du, cut, len, C, out);
}

void phong_span_scalar(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out) {
  const float inv = len > 0 ? 1.0f / static_cast<float>(len) : 0.0f;
  const float dx = n1[0] - n0[0], dy = n1[1] - n0[1], dz = n1[2] - n0[2];
  for (int i = 0; i <= len; ++i) {
    const float t = static_cast<float>(i) * inv;
    const float x = n0[0] + t * dx, y = n0[1] + t * dy, z = n0[2] + t * dz;
    const float c = (x * h[0] + y * h[1] + z * h[2]) / std::sqrt(x * x + y * y + z * z);
    out[i] = c > 0.0f ? C * std::pow(c, n) : 0.0f;
  }
}

}  // namespace detail

}  // namespace specular
