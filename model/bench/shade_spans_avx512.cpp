// SPDX-License-Identifier: Apache-2.0
// AVX-512 variants of the cross-span shaders (model/bench/shade_spans.hpp): stages 1 and 2 and
// the device's stage 3 from shade_spans_kernel.inl (GCC vectorizes stage 3 16 floats wide),
// and the Phong stage 3 of shade_spans_phong_simd.inl 16 pixels at a time with SLEEF's
// Sleef_powf16_u10avx512f (1.0 ulp). Compiled with -mavx512f -mavx512dq -mavx512vl -mfma
// -mprefer-vector-width=512 -ffp-contract=fast (model/bench/CMakeLists.txt) and only called
// after cpu_has_avx512() said yes.
#include "shade_spans.hpp"

#include <immintrin.h>
#include <sleef.h>

#define SHADE_KERNEL_NS shade_avx512
#include "shade_spans_kernel.inl"
#include "shade_spans_phong_simd.inl"
#undef SHADE_KERNEL_NS

namespace specular::host::detail {

void device_shade_avx512(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  shade_avx512::device_shade(t, regs, out);
}

namespace {

// The operations of shade_spans_phong_simd.inl on 16 floats.
struct Avx512Ops {
  using V = __m512;
  static constexpr int kWidth = 16;
  static V set1(float x) { return _mm512_set1_ps(x); }
  static V zero() { return _mm512_setzero_ps(); }
  static V load(const float* p) { return _mm512_loadu_ps(p); }
  static V add(V a, V b) { return _mm512_add_ps(a, b); }
  static V sub(V a, V b) { return _mm512_sub_ps(a, b); }
  static V mul(V a, V b) { return _mm512_mul_ps(a, b); }
  static V div(V a, V b) { return _mm512_div_ps(a, b); }
  static V fmadd(V a, V b, V c) { return _mm512_fmadd_ps(a, b, c); }
  static V max(V a, V b) { return _mm512_max_ps(a, b); }
  static V rsqrt_estimate(V x) { return _mm512_rsqrt14_ps(x); }  // 14 bits
  static V pow(V x, V y) { return Sleef_powf16_u10avx512f(x, y); }
  static V keep_positive(V c, V v) { return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(c, _mm512_setzero_ps(), _CMP_GT_OQ), v); }
  static void store(float* out, V v, int left) {
    if (left >= kWidth)
      _mm512_storeu_ps(out, v);
    else
      _mm512_mask_storeu_ps(out, static_cast<__mmask16>((1u << left) - 1u), v);
  }
};

}  // namespace

void phong_shade_avx512(const PhongSpans& s, float* out) {
  shade_avx512::phong_shade<shade_avx512::PhongSimd<Avx512Ops>>(s, out);
}

}  // namespace specular::host::detail
