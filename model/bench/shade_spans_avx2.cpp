// SPDX-License-Identifier: Apache-2.0
// AVX2 + FMA variants of the cross-span shaders (model/bench/shade_spans.hpp): stages 1 and 2
// and the device's stage 3 from shade_spans_kernel.inl, and the Phong stage 3 of
// shade_spans_phong_simd.inl with SLEEF's Sleef_powf8_u10avx2 (1.0 ulp). Compiled with
// -mavx2 -mfma -ffp-contract=fast (model/bench/CMakeLists.txt) and only called after
// cpu_has_avx2() said yes.
#include "shade_spans.hpp"

#include <immintrin.h>
#include <sleef.h>

#define SHADE_KERNEL_NS shade_avx2
#include "shade_spans_kernel.inl"
#include "shade_spans_phong_simd.inl"
#undef SHADE_KERNEL_NS

namespace specular::host::detail {

void device_shade_avx2(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  shade_avx2::device_shade(t, regs, out);
}

namespace {

// The operations of shade_spans_phong_simd.inl on 8 floats.
struct Avx2Ops {
  using V = __m256;
  static constexpr int kWidth = 8;
  static V set1(float x) { return _mm256_set1_ps(x); }
  static V zero() { return _mm256_setzero_ps(); }
  static V load(const float* p) { return _mm256_loadu_ps(p); }
  static V add(V a, V b) { return _mm256_add_ps(a, b); }
  static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
  static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
  static V div(V a, V b) { return _mm256_div_ps(a, b); }
  static V fmadd(V a, V b, V c) { return _mm256_fmadd_ps(a, b, c); }
  static V max(V a, V b) { return _mm256_max_ps(a, b); }
  static V rsqrt_estimate(V x) { return _mm256_rsqrt_ps(x); }  // 12 bits
  static V pow(V x, V y) { return Sleef_powf8_u10avx2(x, y); }
  static V keep_positive(V c, V v) { return _mm256_and_ps(_mm256_cmp_ps(c, _mm256_setzero_ps(), _CMP_GT_OQ), v); }
  static void store(float* out, V v, int left) {
    if (left >= kWidth) {
      _mm256_storeu_ps(out, v);
    } else {
      const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
      _mm256_maskstore_ps(out, _mm256_cmpgt_epi32(_mm256_set1_epi32(left), lane), v);
    }
  }
};

}  // namespace

void phong_shade_avx2(const PhongSpans& s, float* out) {
  shade_avx2::phong_shade<shade_avx2::PhongSimd<Avx2Ops>>(s, out);
}

}  // namespace specular::host::detail
