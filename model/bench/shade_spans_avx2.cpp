// SPDX-License-Identifier: Apache-2.0
// AVX2 + FMA variants of the cross-span shaders (model/bench/shade_spans.hpp): stages 1 and 2
// and the device's stage 3 from shade_spans_kernel.inl, and the Phong stage 3 with SLEEF's
// Sleef_powf8_u10avx2 (1.0 ulp). Compiled with -mavx2 -mfma -ffp-contract=fast
// (model/bench/CMakeLists.txt) and only called after cpu_has_avx2() said yes.
#include "shade_spans.hpp"

#include <immintrin.h>
#include <sleef.h>

#define SHADE_KERNEL_NS shade_avx2
#include "shade_spans_kernel.inl"
#undef SHADE_KERNEL_NS

namespace specular::host::detail {

void device_shade_avx2(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  shade_avx2::device_shade(t, regs, out);
}

namespace {

// 1 / sqrt(x): the 12-bit estimate and one Newton step (a few ulp).
inline __m256 rsqrt_nr(__m256 x) {
  const __m256 r = _mm256_rsqrt_ps(x);
  const __m256 xrr = _mm256_mul_ps(_mm256_mul_ps(x, r), r);
  return _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), r), _mm256_sub_ps(_mm256_set1_ps(3.0f), xrr));
}

// C c^n where c = dot / sqrt(q) > 0, else 0; stores the first `left` lanes (all when >= 8).
inline void phong_out(__m256 dot, __m256 q, __m256 n, __m256 C, float* out, int left) {
  const __m256 zero = _mm256_setzero_ps();
  const __m256 c = _mm256_mul_ps(dot, rsqrt_nr(q));
  const __m256 pos = _mm256_cmp_ps(c, zero, _CMP_GT_OQ);  // false for NaN (N = 0 or H = 0)
  const __m256 v = _mm256_and_ps(pos, _mm256_mul_ps(C, Sleef_powf8_u10avx2(_mm256_max_ps(c, zero), n)));
  if (left >= 8) {
    _mm256_storeu_ps(out, v);
  } else {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    _mm256_maskstore_ps(out, _mm256_cmpgt_epi32(_mm256_set1_epi32(left), lane), v);
  }
}

void eval_const(const shade_avx2::PhongBuffers& B, int count, float* out) {
  for (int i = 0; i < count; i += 8)
    phong_out(_mm256_loadu_ps(&B.d[i]), _mm256_loadu_ps(&B.q[i]), _mm256_loadu_ps(&B.n[i]), _mm256_loadu_ps(&B.c[i]),
              out + i, count - i);
}

template <bool Point, bool Persp>
void eval_pp(const shade_avx2::PhongBuffers& B, int count, const PhongGroup& g, float* out) {
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256 gx = _mm256_set1_ps(g.light[0]), gy = _mm256_set1_ps(g.light[1]), gz = _mm256_set1_ps(g.light[2]);
  const __m256 ex = _mm256_set1_ps(g.viewer[0]), ey = _mm256_set1_ps(g.viewer[1]), ez = _mm256_set1_ps(g.viewer[2]);
  for (int i = 0; i < count; i += 8) {
    const __m256 r = _mm256_div_ps(one, _mm256_loadu_ps(&B.den[i]));
    const __m256 px = _mm256_mul_ps(_mm256_loadu_ps(&B.px[i]), r);
    const __m256 py = _mm256_mul_ps(_mm256_loadu_ps(&B.py[i]), r);
    const __m256 pz = _mm256_mul_ps(_mm256_loadu_ps(&B.pz[i]), r);
    __m256 lx = gx, ly = gy, lz = gz;
    if constexpr (Point) {
      lx = _mm256_sub_ps(gx, px), ly = _mm256_sub_ps(gy, py), lz = _mm256_sub_ps(gz, pz);
      const __m256 s = rsqrt_nr(_mm256_fmadd_ps(lx, lx, _mm256_fmadd_ps(ly, ly, _mm256_mul_ps(lz, lz))));
      lx = _mm256_mul_ps(lx, s), ly = _mm256_mul_ps(ly, s), lz = _mm256_mul_ps(lz, s);
    }
    __m256 vx = ex, vy = ey, vz = ez;
    if constexpr (Persp) {
      vx = _mm256_sub_ps(ex, px), vy = _mm256_sub_ps(ey, py), vz = _mm256_sub_ps(ez, pz);
      const __m256 s = rsqrt_nr(_mm256_fmadd_ps(vx, vx, _mm256_fmadd_ps(vy, vy, _mm256_mul_ps(vz, vz))));
      vx = _mm256_mul_ps(vx, s), vy = _mm256_mul_ps(vy, s), vz = _mm256_mul_ps(vz, s);
    }
    const __m256 hx = _mm256_add_ps(lx, vx), hy = _mm256_add_ps(ly, vy), hz = _mm256_add_ps(lz, vz);
    const __m256 nx = _mm256_loadu_ps(&B.nx[i]), ny = _mm256_loadu_ps(&B.ny[i]), nz = _mm256_loadu_ps(&B.nz[i]);
    const __m256 dot = _mm256_fmadd_ps(nx, hx, _mm256_fmadd_ps(ny, hy, _mm256_mul_ps(nz, hz)));
    const __m256 nn = _mm256_fmadd_ps(nx, nx, _mm256_fmadd_ps(ny, ny, _mm256_mul_ps(nz, nz)));
    const __m256 hh = _mm256_fmadd_ps(hx, hx, _mm256_fmadd_ps(hy, hy, _mm256_mul_ps(hz, hz)));
    phong_out(dot, _mm256_mul_ps(nn, hh), _mm256_loadu_ps(&B.n[i]), _mm256_loadu_ps(&B.c[i]), out + i, count - i);
  }
}

}  // namespace

void phong_shade_avx2(const PhongSpans& s, float* out) {
  shade_avx2::phong_shade(s, out, eval_const, [](const shade_avx2::PhongBuffers& B, int count, const PhongGroup& g, float* o) {
    if (g.point_light && g.perspective)
      eval_pp<true, true>(B, count, g, o);
    else if (g.point_light)
      eval_pp<true, false>(B, count, g, o);
    else
      eval_pp<false, true>(B, count, g, o);
  });
}

}  // namespace specular::host::detail
