// SPDX-License-Identifier: Apache-2.0
// AVX-512 variants of the cross-span shaders (model/bench/shade_spans.hpp): stages 1 and 2 and
// the device's stage 3 from shade_spans_kernel.inl (GCC vectorizes stage 3 16 floats wide),
// and the Phong stage 3 16 pixels at a time with SLEEF's Sleef_powf16_u10avx512f (1.0 ulp).
// The AVX2 file (shade_spans_avx2.cpp) with 512-bit registers. Compiled with -mavx512f
// -mavx512dq -mavx512vl -mfma -mprefer-vector-width=512 -ffp-contract=fast
// (model/bench/CMakeLists.txt) and only called after cpu_has_avx512() said yes.
#include "shade_spans.hpp"

#include <immintrin.h>
#include <sleef.h>

#define SHADE_KERNEL_NS shade_avx512
#include "shade_spans_kernel.inl"
#undef SHADE_KERNEL_NS

namespace specular::host::detail {

void device_shade_avx512(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  shade_avx512::device_shade(t, regs, out);
}

namespace {

// 1 / sqrt(x): the 14-bit estimate and one Newton step (a few ulp).
inline __m512 rsqrt_nr(__m512 x) {
  const __m512 r = _mm512_rsqrt14_ps(x);
  const __m512 xrr = _mm512_mul_ps(_mm512_mul_ps(x, r), r);
  return _mm512_mul_ps(_mm512_mul_ps(_mm512_set1_ps(0.5f), r), _mm512_sub_ps(_mm512_set1_ps(3.0f), xrr));
}

// C c^n where c = dot / sqrt(q) > 0, else 0; stores the first `left` lanes (all when >= 16).
inline void phong_out(__m512 dot, __m512 q, __m512 n, __m512 C, float* out, int left) {
  const __m512 zero = _mm512_setzero_ps();
  const __m512 c = _mm512_mul_ps(dot, rsqrt_nr(q));
  const __mmask16 pos = _mm512_cmp_ps_mask(c, zero, _CMP_GT_OQ);  // false for NaN (N = 0 or H = 0)
  const __m512 v = _mm512_maskz_mov_ps(pos, _mm512_mul_ps(C, Sleef_powf16_u10avx512f(_mm512_max_ps(c, zero), n)));
  if (left >= 16)
    _mm512_storeu_ps(out, v);
  else
    _mm512_mask_storeu_ps(out, static_cast<__mmask16>((1u << left) - 1u), v);
}

void eval_const(const shade_avx512::PhongBuffers& B, int count, float* out) {
  for (int i = 0; i < count; i += 16)
    phong_out(_mm512_loadu_ps(&B.d[i]), _mm512_loadu_ps(&B.q[i]), _mm512_loadu_ps(&B.n[i]), _mm512_loadu_ps(&B.c[i]),
              out + i, count - i);
}

template <bool Point, bool Persp>
void eval_pp(const shade_avx512::PhongBuffers& B, int count, const PhongGroup& g, float* out) {
  const __m512 one = _mm512_set1_ps(1.0f);
  const __m512 gx = _mm512_set1_ps(g.light[0]), gy = _mm512_set1_ps(g.light[1]), gz = _mm512_set1_ps(g.light[2]);
  const __m512 ex = _mm512_set1_ps(g.viewer[0]), ey = _mm512_set1_ps(g.viewer[1]), ez = _mm512_set1_ps(g.viewer[2]);
  for (int i = 0; i < count; i += 16) {
    const __m512 r = _mm512_div_ps(one, _mm512_loadu_ps(&B.den[i]));
    const __m512 px = _mm512_mul_ps(_mm512_loadu_ps(&B.px[i]), r);
    const __m512 py = _mm512_mul_ps(_mm512_loadu_ps(&B.py[i]), r);
    const __m512 pz = _mm512_mul_ps(_mm512_loadu_ps(&B.pz[i]), r);
    __m512 lx = gx, ly = gy, lz = gz;
    if constexpr (Point) {
      lx = _mm512_sub_ps(gx, px), ly = _mm512_sub_ps(gy, py), lz = _mm512_sub_ps(gz, pz);
      const __m512 s = rsqrt_nr(_mm512_fmadd_ps(lx, lx, _mm512_fmadd_ps(ly, ly, _mm512_mul_ps(lz, lz))));
      lx = _mm512_mul_ps(lx, s), ly = _mm512_mul_ps(ly, s), lz = _mm512_mul_ps(lz, s);
    }
    __m512 vx = ex, vy = ey, vz = ez;
    if constexpr (Persp) {
      vx = _mm512_sub_ps(ex, px), vy = _mm512_sub_ps(ey, py), vz = _mm512_sub_ps(ez, pz);
      const __m512 s = rsqrt_nr(_mm512_fmadd_ps(vx, vx, _mm512_fmadd_ps(vy, vy, _mm512_mul_ps(vz, vz))));
      vx = _mm512_mul_ps(vx, s), vy = _mm512_mul_ps(vy, s), vz = _mm512_mul_ps(vz, s);
    }
    const __m512 hx = _mm512_add_ps(lx, vx), hy = _mm512_add_ps(ly, vy), hz = _mm512_add_ps(lz, vz);
    const __m512 nx = _mm512_loadu_ps(&B.nx[i]), ny = _mm512_loadu_ps(&B.ny[i]), nz = _mm512_loadu_ps(&B.nz[i]);
    const __m512 dot = _mm512_fmadd_ps(nx, hx, _mm512_fmadd_ps(ny, hy, _mm512_mul_ps(nz, hz)));
    const __m512 nn = _mm512_fmadd_ps(nx, nx, _mm512_fmadd_ps(ny, ny, _mm512_mul_ps(nz, nz)));
    const __m512 hh = _mm512_fmadd_ps(hx, hx, _mm512_fmadd_ps(hy, hy, _mm512_mul_ps(hz, hz)));
    phong_out(dot, _mm512_mul_ps(nn, hh), _mm512_loadu_ps(&B.n[i]), _mm512_loadu_ps(&B.c[i]), out + i, count - i);
  }
}

}  // namespace

void phong_shade_avx512(const PhongSpans& s, float* out) {
  shade_avx512::phong_shade(s, out, eval_const, [](const shade_avx512::PhongBuffers& B, int count, const PhongGroup& g, float* o) {
    if (g.point_light && g.perspective)
      eval_pp<true, true>(B, count, g, o);
    else if (g.point_light)
      eval_pp<true, false>(B, count, g, o);
    else
      eval_pp<false, true>(B, count, g, o);
  });
}

}  // namespace specular::host::detail
