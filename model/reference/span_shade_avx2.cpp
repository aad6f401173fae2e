// SPDX-License-Identifier: Apache-2.0
// AVX2 + FMA variants of the span kernels (model/reference/span_shade.hpp). This file is compiled
// with -mavx2 -mfma -ffp-contract=fast (model/CMakeLists.txt) and only ever called after
// cpu_has_avx2() said yes; nothing here runs at static-initialization time.
#include "span_shade.hpp"

#include <immintrin.h>
#include <sleef.h>

#define SPAN_KERNEL_NS avx2_kernels
#include "span_shade_kernel.inl"
#undef SPAN_KERNEL_NS

namespace specular::detail {

void device_span_avx2(int k, float u0, float du, float cut, int len, float C, float* out) {
  avx2_kernels::device_dispatch(k, u0, du, cut, len, C, out);
}

// Per-pixel Phong, 8 pixels per step: lerp N, |N| by sqrt, c = N.h / |N|, SLEEF powf8.
void phong_span_avx2(const Vec3f& n0, const Vec3f& n1, const Vec3f& h, float n, int len, float C, float* out) {
  if (len < 0) return;
  const float inv = len > 0 ? 1.0f / static_cast<float>(len) : 0.0f;
  const __m256 x0 = _mm256_set1_ps(n0[0]), y0 = _mm256_set1_ps(n0[1]), z0 = _mm256_set1_ps(n0[2]);
  const __m256 dx = _mm256_set1_ps(n1[0] - n0[0]), dy = _mm256_set1_ps(n1[1] - n0[1]),
               dz = _mm256_set1_ps(n1[2] - n0[2]);
  const __m256 hx = _mm256_set1_ps(h[0]), hy = _mm256_set1_ps(h[1]), hz = _mm256_set1_ps(h[2]);
  const __m256 vn = _mm256_set1_ps(n), vc = _mm256_set1_ps(C), vinv = _mm256_set1_ps(inv);
  const __m256 zero = _mm256_setzero_ps();
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const int count = len + 1;
  for (int i = 0; i < count; i += 8) {
    const __m256 t = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_add_epi32(_mm256_set1_epi32(i), lane)), vinv);
    const __m256 x = _mm256_fmadd_ps(t, dx, x0), y = _mm256_fmadd_ps(t, dy, y0), z = _mm256_fmadd_ps(t, dz, z0);
    const __m256 len2 = _mm256_fmadd_ps(x, x, _mm256_fmadd_ps(y, y, _mm256_mul_ps(z, z)));
    const __m256 dot = _mm256_fmadd_ps(x, hx, _mm256_fmadd_ps(y, hy, _mm256_mul_ps(z, hz)));
    const __m256 c = _mm256_div_ps(dot, _mm256_sqrt_ps(len2));
    const __m256 pos = _mm256_cmp_ps(c, zero, _CMP_GT_OQ);  // false for NaN (N = 0)
    const __m256 v = _mm256_and_ps(pos, _mm256_mul_ps(vc, Sleef_powf8_u10avx2(_mm256_max_ps(c, zero), vn)));
    if (count - i >= 8) {
      _mm256_storeu_ps(out + i, v);
    } else {
      alignas(32) float tail[8];
      _mm256_store_ps(tail, v);
      for (int j = 0; j < count - i; ++j) out[i + j] = tail[j];
    }
  }
}

}  // namespace specular::detail
