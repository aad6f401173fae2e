// SPDX-License-Identifier: Apache-2.0
// Stages 1 and 2 of the cross-span shaders (model/bench/shade_spans.hpp) and the device
// method's stage 3, compiled twice: by shade_spans.cpp for the x86-64 baseline and by
// shade_spans_avx2.cpp with -mavx2 -mfma -ffp-contract=fast. Each includes this file inside
// its own namespace (SHADE_KERNEL_NS), so the two instantiations never merge at link time.
// Stage 2 uses GCC vector extensions (8 floats: one AVX register, two SSE registers in the
// baseline build); stage 3 of the device is a plain loop GCC vectorizes, with the polynomial
// and the powering chain of device_span (model/reference/span_shade_kernel.inl, included here
// under a namespace of this file's own).
#include "shade_spans.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#define SPAN_KERNEL_NS SHADE_KERNEL_NS
#include "span_shade_kernel.inl"
#undef SPAN_KERNEL_NS

// Vectors of 8 floats passed between inline functions of this file only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace specular::host::SHADE_KERNEL_NS {

using v8f = float __attribute__((vector_size(32)));

inline constexpr int kMaxPixels = kMaxLen + 1;  // l <= kMaxLen (counter 5, scanline_setup.hpp)
inline constexpr int kSpanBlock = 256;       // stage 1 block (its arrays stay in L1)
inline constexpr int kCapacity = kMaxPixels + 8;  // a buffer holds one whole span and the 8-lane surplus

inline v8f splat(float x) { return v8f{x, x, x, x, x, x, x, x}; }
inline void store8(float* p, v8f v) { std::memcpy(p, &v, sizeof v); }
inline const v8f kLane{0, 1, 2, 3, 4, 5, 6, 7};

// ------------------------------------------------------------------------- device method

// C cos^k(u) for |u| < cut, else 0 (device_span's kernel, u and C per pixel).
template <int K>
void device_eval(const float* __restrict u, const float* __restrict C, int count, float cut, float* __restrict out) {
  for (int i = 0; i < count; ++i) {
    const float x = u[i];
    const float c = specular::SHADE_KERNEL_NS::cos_poly(x);
    const float v = C[i] * specular::SHADE_KERNEL_NS::powk<K>(c > 0.0f ? c : 0.0f);
    out[i] = std::abs(x) < cut ? v : 0.0f;
  }
}

inline void device_eval_k(int k, const float* u, const float* C, int count, float cut, float* out) {
  switch (k) {
#define SHADE_BANK(K) \
  case K: device_eval<K>(u, C, count, cut, out); break;
    SHADE_BANK(1) SHADE_BANK(2) SHADE_BANK(3) SHADE_BANK(4) SHADE_BANK(5) SHADE_BANK(6) SHADE_BANK(7)
    SHADE_BANK(8) SHADE_BANK(12) SHADE_BANK(16) SHADE_BANK(24) SHADE_BANK(32) SHADE_BANK(48) SHADE_BANK(64)
#undef SHADE_BANK
    default: throw std::logic_error("shade_spans: k outside the bank set of device_span_plan");
  }
}

// Stage 3 over the buffer: one device_eval per run of spans with one k.
[[gnu::noinline]] inline void device_flush(const DeviceShader::Tables& t, const float* ubuf, const float* cbuf,
                                           const int32_t* run_begin, const int32_t* run_k, int runs, int fill,
                                           float* out) {
  for (int r = 0; r < runs; ++r) {
    const int b = run_begin[r], e = r + 1 < runs ? run_begin[r + 1] : fill;
    if (e > b) device_eval_k(run_k[r], ubuf + b, cbuf + b, e - b, t.cut, out + b);
  }
}

// The stage-2 buffer and where its pixels go.
struct DeviceBuffer {
  float* ubuf;
  float* cbuf;
  int32_t* run_begin;  // runs of one k: [run_begin[r], run_begin[r + 1]) with k = run_k[r]
  int32_t* run_k;
  int fill, runs, cur_k;
  float* dst;  // where the buffer's pixel 0 goes
};

inline constexpr int kDeviceFlushAt = 1024;  // pixels per stage-3 pass: u and C stay in L1

// Stage 2 for m spans: u_i = u0 + i du and C, 8 lanes per store. A function of its own, so
// that the fill level stays in a register (in the caller it was spilled, and the store and
// reload of it bounded the loop).
[[gnu::noinline]] inline void device_expand(const DeviceShader::Tables& t, const float* __restrict u0,
                                            const float* __restrict du, const float* __restrict cc,
                                            const int32_t* __restrict kk, const int32_t* __restrict cnt, int m,
                                            DeviceBuffer& st) {
  float* const ubuf = st.ubuf;
  float* const cbuf = st.cbuf;
  int fill = st.fill, cur_k = st.cur_k;
  for (int j = 0; j < m; ++j) {
    const int n = cnt[j];
    if (__builtin_expect(fill + n > kDeviceFlushAt || kk[j] != cur_k, 0)) {
      if (fill + n > kDeviceFlushAt) {
        device_flush(t, ubuf, cbuf, st.run_begin, st.run_k, st.runs, fill, st.dst);
        st.dst += fill;
        fill = 0, st.runs = 1, st.run_begin[0] = 0, st.run_k[0] = cur_k;
      }
      if (kk[j] != cur_k) {
        cur_k = kk[j];
        if (st.run_begin[st.runs - 1] == fill)
          st.run_k[st.runs - 1] = cur_k;
        else
          st.run_begin[st.runs] = fill, st.run_k[st.runs] = cur_k, ++st.runs;
      }
    }
    const v8f vu0 = splat(u0[j]), vdu = splat(du[j]), vc = splat(cc[j]);
    float* pu = ubuf + fill;
    float* pc = cbuf + fill;
    store8(pu, vu0 + kLane * vdu);
    store8(pc, vc);
    for (int i = 8; i < n; i += 8) {
      store8(pu + i, vu0 + (kLane + splat(static_cast<float>(i))) * vdu);
      store8(pc + i, vc);
    }
    fill += n;
  }
  st.fill = fill, st.cur_k = cur_k;
}

// Stage 2 for a block of spans with one k that fits the buffer as a whole: no test per span.
[[gnu::noinline]] inline int device_expand_fast(const float* __restrict u0, const float* __restrict du,
                                                const float* __restrict cc, const int32_t* __restrict cnt, int m,
                                                float* __restrict ubuf, float* __restrict cbuf, int fill) {
  for (int j = 0; j < m; ++j) {
    const int n = cnt[j];
    const v8f vu0 = splat(u0[j]), vdu = splat(du[j]), vc = splat(cc[j]);
    float* pu = ubuf + fill;
    float* pc = cbuf + fill;
    store8(pu, vu0 + kLane * vdu);
    store8(pc, vc);
    for (int i = 8; i < n; i += 8) {
      store8(pu + i, vu0 + (kLane + splat(static_cast<float>(i))) * vdu);
      store8(pc + i, vc);
    }
    fill += n;
  }
  return fill;
}

inline void device_shade(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  constexpr int kBuf = kCapacity + 2 * kDeviceFlushAt;
  std::vector<float> ubuf_v(kBuf), cbuf_v(kBuf);
  std::vector<int32_t> run_begin_v(kBuf + 1), run_k_v(kBuf + 1);
  DeviceBuffer st{ubuf_v.data(), cbuf_v.data(), run_begin_v.data(), run_k_v.data(), 0, 1, 1, out};
  st.run_begin[0] = 0, st.run_k[0] = 1;
  alignas(64) float u0[kSpanBlock], du[kSpanBlock], cc[kSpanBlock];
  alignas(64) int32_t kk[kSpanBlock], cnt[kSpanBlock];
  const uint32_t top = static_cast<uint32_t>(t.a.size()) - 1;  // codes above max_n are invalid (a = 0)
  const double* __restrict ta = t.a_scaled.data();
  const double* __restrict tc = t.c_scale.data();
  const int32_t* __restrict tk = t.k.data();
  const bool narrow = t.narrow;
  const size_t total = regs.size();
  for (size_t b0 = 0; b0 < total; b0 += kSpanBlock) {
    const int m = static_cast<int>(std::min<size_t>(kSpanBlock, total - b0));
    const uint32_t* __restrict rc = &regs.c[b0];
    const int64_t* __restrict rp = &regs.psi0[b0];
    const int64_t* __restrict rd = &regs.dpsi[b0];
    const uint32_t* __restrict rn = &regs.n[b0];
    const uint32_t* __restrict rl = &regs.len[b0];
    // Stage 1: u0 = a psi0, du = a dpsi rounded to float from double (device_span's
    // arithmetic; a_scaled = a 2^-angle_frac, exact); invalid n codes: a = 0, C = 0.
    uint32_t longest = 0, differ = 0, block_pixels = 0;
    for (int j = 0; j < m; ++j) {
      cnt[j] = static_cast<int32_t>(rl[j]) + 1;
      longest = longest > rl[j] ? longest : rl[j];
      differ |= rn[j] ^ rn[0];
      block_pixels += rl[j] + 1;
    }
    if (narrow && differ == 0) {
      // One n in the block (spans come material by material): a, C's scale and k are
      // constants, no table look-up per span. Angle codes fit int32 (angle_bits <= 32).
      const uint32_t nc = rn[0] < top ? rn[0] : top;
      const double a = ta[nc], cs = tc[nc];
      for (int j = 0; j < m; ++j) {
        u0[j] = static_cast<float>(a * static_cast<double>(static_cast<int32_t>(rp[j])));
        du[j] = static_cast<float>(a * static_cast<double>(static_cast<int32_t>(rd[j])));
        cc[j] = static_cast<float>(static_cast<double>(static_cast<int32_t>(rc[j])) * cs);
        kk[j] = tk[nc];
      }
    } else if (narrow) {
      for (int j = 0; j < m; ++j) {
        const uint32_t nc = rn[j] < top ? rn[j] : top;
        const double a = ta[nc];
        u0[j] = static_cast<float>(a * static_cast<double>(static_cast<int32_t>(rp[j])));
        du[j] = static_cast<float>(a * static_cast<double>(static_cast<int32_t>(rd[j])));
        cc[j] = static_cast<float>(static_cast<double>(static_cast<int32_t>(rc[j])) * tc[nc]);
        kk[j] = tk[nc];
      }
    } else {
      for (int j = 0; j < m; ++j) {
        const uint32_t nc = rn[j] < top ? rn[j] : top;
        const double a = ta[nc];
        u0[j] = static_cast<float>(a * static_cast<double>(rp[j]));
        du[j] = static_cast<float>(a * static_cast<double>(rd[j]));
        cc[j] = static_cast<float>(static_cast<double>(rc[j]) * tc[nc]);
        kk[j] = tk[nc];
      }
    }
    if (longest >= static_cast<uint32_t>(kMaxPixels)) throw std::invalid_argument("DeviceShader::shade: len above " + std::to_string(kMaxLen));
    if (narrow && differ == 0 && block_pixels + 8 <= static_cast<uint32_t>(kBuf)) {
      // One k for the block and room for all of it: the run and the flush are decided once.
      if (st.fill + static_cast<int>(block_pixels) + 8 > kBuf) {
        device_flush(t, st.ubuf, st.cbuf, st.run_begin, st.run_k, st.runs, st.fill, st.dst);
        st.dst += st.fill;
        st.fill = 0, st.runs = 1, st.run_begin[0] = 0, st.run_k[0] = st.cur_k;
      }
      if (kk[0] != st.cur_k) {
        st.cur_k = kk[0];
        if (st.run_begin[st.runs - 1] == st.fill)
          st.run_k[st.runs - 1] = st.cur_k;
        else
          st.run_begin[st.runs] = st.fill, st.run_k[st.runs] = st.cur_k, ++st.runs;
      }
      st.fill = device_expand_fast(u0, du, cc, cnt, m, st.ubuf, st.cbuf, st.fill);
      if (st.fill >= kDeviceFlushAt) {
        device_flush(t, st.ubuf, st.cbuf, st.run_begin, st.run_k, st.runs, st.fill, st.dst);
        st.dst += st.fill;
        st.fill = 0, st.runs = 1, st.run_begin[0] = 0, st.run_k[0] = st.cur_k;
      }
    } else {
      device_expand(t, u0, du, cc, kk, cnt, m, st);
    }
  }
  device_flush(t, st.ubuf, st.cbuf, st.run_begin, st.run_k, st.runs, st.fill, st.dst);
}

// ------------------------------------------------------------------------- Phong

// Stage-2 buffers of the Phong shaders, one stage-3 pass at a time.
struct PhongBuffers {
  static constexpr int kFlushAt = 512;  // 9 floats per pixel (per-pixel H): 18 KB per pass
  static constexpr int kSize = kCapacity + 2 * kFlushAt;
  std::vector<float> d, q;              // constant H: N.H and |N|^2
  std::vector<float> nx, ny, nz, px, py, pz, den;  // per-pixel H: N, P numerator and denominator
  std::vector<float> n, c;              // exponent, C
  PhongBuffers() {
    for (auto* v : {&d, &q, &nx, &ny, &nz, &px, &py, &pz, &den, &n, &c}) v->assign(kSize + 16, 0.0f);  // + 16: a 16-wide stage 3 reads past the last pixel
  }
};

// Stage 2 of constant-H spans (a function of its own: the fill level stays in a register).
// Returns the new fill level; full buffers go to eval(B, fill, dst) and dst advances.
// Check = false: the caller made room for the whole block (no test per span).
template <bool Check, class Eval>
[[gnu::noinline]] int phong_expand_const(const float* __restrict a, const float* __restrict b,
                                         const float* __restrict q0, const float* __restrict q1,
                                         const float* __restrict q2, const float* __restrict sn,
                                         const float* __restrict sc, const int32_t* __restrict cnt, int m, int fill,
                                         PhongBuffers& B, float*& dst, Eval& eval) {
  float* const bd = B.d.data();
  float* const bq = B.q.data();
  float* const bn = B.n.data();
  float* const bc = B.c.data();
  for (int j = 0; j < m; ++j) {
    const int n = cnt[j];
    if (Check && __builtin_expect(fill + n > PhongBuffers::kFlushAt, 0)) {
      eval(B, fill, dst);
      dst += fill;
      fill = 0;
    }
    const v8f va = splat(a[j]), vb = splat(b[j]), v0 = splat(q0[j]), v1 = splat(q1[j]), v2 = splat(q2[j]);
    const v8f vn = splat(sn[j]), vc = splat(sc[j]);
    for (int i = 0; i < n; i += 8) {
      const v8f x = kLane + splat(static_cast<float>(i));
      store8(bd + fill + i, va + x * vb);
      store8(bq + fill + i, v0 + x * (v1 + x * v2));
      store8(bn + fill + i, vn);
      store8(bc + fill + i, vc);
    }
    fill += n;
  }
  return fill;
}

// Stage 2 of per-pixel-H spans: k[0..2] slope of N, k[3..5] P1/w1, k[6..8] slope of P/w,
// k[9] 1/w1, k[10] slope of 1/w, k[11..13] N1.
template <bool Check, class Eval>
[[gnu::noinline]] int phong_expand_pp(const float* const (&k)[14], const float* __restrict sn,
                                      const float* __restrict sc, const int32_t* __restrict cnt, int m, int fill,
                                      PhongBuffers& B, float*& dst, const PhongGroup& g, Eval& eval) {
  float* const bnx = B.nx.data();
  float* const bny = B.ny.data();
  float* const bnz = B.nz.data();
  float* const bpx = B.px.data();
  float* const bpy = B.py.data();
  float* const bpz = B.pz.data();
  float* const bden = B.den.data();
  float* const bn = B.n.data();
  float* const bc = B.c.data();
  for (int j = 0; j < m; ++j) {
    const int n = cnt[j];
    if (Check && __builtin_expect(fill + n > PhongBuffers::kFlushAt, 0)) {
      eval(B, fill, g, dst);
      dst += fill;
      fill = 0;
    }
    const v8f vn = splat(sn[j]), vc = splat(sc[j]);
    for (int i = 0; i < n; i += 8) {
      const v8f x = kLane + splat(static_cast<float>(i));
      store8(bnx + fill + i, splat(k[11][j]) + x * splat(k[0][j]));
      store8(bny + fill + i, splat(k[12][j]) + x * splat(k[1][j]));
      store8(bnz + fill + i, splat(k[13][j]) + x * splat(k[2][j]));
      store8(bpx + fill + i, splat(k[3][j]) + x * splat(k[6][j]));
      store8(bpy + fill + i, splat(k[4][j]) + x * splat(k[7][j]));
      store8(bpz + fill + i, splat(k[5][j]) + x * splat(k[8][j]));
      store8(bden + fill + i, splat(k[9][j]) + x * splat(k[10][j]));
      store8(bn + fill + i, vn);
      store8(bc + fill + i, vc);
    }
    fill += n;
  }
  return fill;
}

// Stage 1 of constant-H spans (restrict parameters: GCC vectorizes it over spans).
// N_i = N1 + (i / l)(N2 - N1), so N_i.H = N1.H + i (D.H / l) and
// |N_i|^2 = |N1|^2 + i (2 N1.D / l + i |D|^2 / l^2) with D = N2 - N1.
inline void phong_stage1_const(const float* __restrict ax, const float* __restrict ay, const float* __restrict az,
                               const float* __restrict bx, const float* __restrict by, const float* __restrict bz,
                               const float* __restrict hx, const float* __restrict hy, const float* __restrict hz,
                               const int32_t* __restrict ll, int m, float* __restrict k0, float* __restrict k1,
                               float* __restrict k2, float* __restrict k3, float* __restrict k4) {
  for (int j = 0; j < m; ++j) {
    const float inv = ll[j] > 0 ? 1.0f / static_cast<float>(ll[j]) : 0.0f;
    const float dx = bx[j] - ax[j], dy = by[j] - ay[j], dz = bz[j] - az[j];
    k0[j] = ax[j] * hx[j] + ay[j] * hy[j] + az[j] * hz[j];
    k1[j] = (dx * hx[j] + dy * hy[j] + dz * hz[j]) * inv;
    k2[j] = ax[j] * ax[j] + ay[j] * ay[j] + az[j] * az[j];
    k3[j] = 2.0f * (ax[j] * dx + ay[j] * dy + az[j] * dz) * inv;
    k4[j] = (dx * dx + dy * dy + dz * dz) * inv * inv;
  }
}

// Stage 1 of per-pixel-H spans: N_i = N1 + i D / l; the surface point (raster.hpp span_point)
// P_i = (P1/w1 + i (P2/w2 - P1/w1) / l) / (1/w1 + i (1/w2 - 1/w1) / l). Outputs as
// phong_expand_pp reads them.
inline void phong_stage1_pp(const float* __restrict ax, const float* __restrict ay, const float* __restrict az,
                            const float* __restrict bx, const float* __restrict by, const float* __restrict bz,
                            const float* __restrict p1x, const float* __restrict p1y, const float* __restrict p1z,
                            const float* __restrict p2x, const float* __restrict p2y, const float* __restrict p2z,
                            const float* __restrict w1, const float* __restrict w2, const int32_t* __restrict ll, int m,
                            float* __restrict k0, float* __restrict k1, float* __restrict k2, float* __restrict k3,
                            float* __restrict k4, float* __restrict k5, float* __restrict k6, float* __restrict k7,
                            float* __restrict k8, float* __restrict k9, float* __restrict k10, float* __restrict k11,
                            float* __restrict k12, float* __restrict k13) {
  for (int j = 0; j < m; ++j) {
    const float inv = ll[j] > 0 ? 1.0f / static_cast<float>(ll[j]) : 0.0f;
    const float r1 = 1.0f / w1[j], r2 = 1.0f / w2[j];
    const float q1x = p1x[j] * r1, q1y = p1y[j] * r1, q1z = p1z[j] * r1;
    k0[j] = (bx[j] - ax[j]) * inv;
    k1[j] = (by[j] - ay[j]) * inv;
    k2[j] = (bz[j] - az[j]) * inv;
    k3[j] = q1x;
    k4[j] = q1y;
    k5[j] = q1z;
    k6[j] = (p2x[j] * r2 - q1x) * inv;
    k7[j] = (p2y[j] * r2 - q1y) * inv;
    k8[j] = (p2z[j] * r2 - q1z) * inv;
    k9[j] = r1;
    k10[j] = (r2 - r1) * inv;
    k11[j] = ax[j];
    k12[j] = ay[j];
    k13[j] = az[j];
  }
}

// Stage 3 of per-pixel-H groups for a variant's Stage3 (below): its pp<Point, Persp> for the
// group's light and viewer (a group with neither is constant-H).
template <class Stage3>
struct PhongEvalPP {
  void operator()(const PhongBuffers& B, int count, const PhongGroup& g, float* out) const {
    if (g.point_light && g.perspective)
      Stage3::template pp<true, true>(B, count, g, out);
    else if (g.point_light)
      Stage3::template pp<true, false>(B, count, g, out);
    else
      Stage3::template pp<false, true>(B, count, g, out);
  }
};

// Runs one group of spans through stages 1 and 2 and hands each filled buffer to stage 3 of
// `Stage3`: Stage3::constant(buffers, count, out) for constant-H groups,
// Stage3::pp<Point, Persp>(buffers, count, group, out) otherwise.
template <class Stage3>
void phong_shade(const PhongSpans& s, float* out) {
  const auto eval_const = [](const PhongBuffers& B, int count, float* o) { Stage3::constant(B, count, o); };
  const PhongEvalPP<Stage3> eval_pp;
  PhongBuffers B;
  float* dst = out;
  alignas(64) float k0[kSpanBlock], k1[kSpanBlock], k2[kSpanBlock], k3[kSpanBlock], k4[kSpanBlock],
      k5[kSpanBlock], k6[kSpanBlock], k7[kSpanBlock], k8[kSpanBlock], k9[kSpanBlock], k10[kSpanBlock],
      k11[kSpanBlock], k12[kSpanBlock], k13[kSpanBlock];
  alignas(64) int32_t cnt[kSpanBlock];
  for (const PhongGroup& g : s.groups) {
    int fill = 0;
    for (size_t b0 = g.begin; b0 < g.end; b0 += kSpanBlock) {
      const int m = static_cast<int>(std::min<size_t>(kSpanBlock, g.end - b0));
      const float* __restrict ax = &s.n1x[b0];
      const float* __restrict ay = &s.n1y[b0];
      const float* __restrict az = &s.n1z[b0];
      const float* __restrict bx = &s.n2x[b0];
      const float* __restrict by = &s.n2y[b0];
      const float* __restrict bz = &s.n2z[b0];
      const int32_t* __restrict ll = &s.l[b0];
      const float* __restrict sn = &s.n[b0];
      const float* __restrict sc = &s.scale[b0];
      uint32_t longest = 0, block_pixels = 0;
      for (int j = 0; j < m; ++j) {
        cnt[j] = ll[j] + 1;
        const uint32_t u = static_cast<uint32_t>(ll[j]);
        longest = longest > u ? longest : u;
        block_pixels += u + 1;
      }
      if (longest >= static_cast<uint32_t>(kMaxPixels)) throw std::invalid_argument("shade_phong: l outside 0.." + std::to_string(kMaxLen));
      // Room for the whole block (the same rule as the device's): no test per span.
      const bool whole = block_pixels + 8 <= static_cast<uint32_t>(PhongBuffers::kSize);
      if (whole && fill + static_cast<int>(block_pixels) + 8 > PhongBuffers::kSize) {
        if (g.constant_h)
          eval_const(B, fill, dst);
        else
          eval_pp(B, fill, g, dst);
        dst += fill;
        fill = 0;
      }
      if (g.constant_h) {
        phong_stage1_const(ax, ay, az, bx, by, bz, &s.hx[b0], &s.hy[b0], &s.hz[b0], ll, m, k0, k1, k2, k3, k4);
        // Stage 2.
        fill = whole ? phong_expand_const<false>(k0, k1, k2, k3, k4, sn, sc, cnt, m, fill, B, dst, eval_const)
                     : phong_expand_const<true>(k0, k1, k2, k3, k4, sn, sc, cnt, m, fill, B, dst, eval_const);
      } else {
        phong_stage1_pp(ax, ay, az, bx, by, bz, &s.p1x[b0], &s.p1y[b0], &s.p1z[b0], &s.p2x[b0], &s.p2y[b0], &s.p2z[b0],
                        &s.w1[b0], &s.w2[b0], ll, m, k0, k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13);
        // Stage 2.
        const float* const k[14] = {k0, k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, k13};
        fill = whole ? phong_expand_pp<false>(k, sn, sc, cnt, m, fill, B, dst, g, eval_pp)
                     : phong_expand_pp<true>(k, sn, sc, cnt, m, fill, B, dst, g, eval_pp);
      }
      if (whole && fill >= PhongBuffers::kFlushAt) {
        if (g.constant_h)
          eval_const(B, fill, dst);
        else
          eval_pp(B, fill, g, dst);
        dst += fill;
        fill = 0;
      }
    }
    if (fill > 0) {
      if (g.constant_h)
        eval_const(B, fill, dst);
      else
        eval_pp(B, fill, g, dst);
      dst += fill;
    }
  }
}

}  // namespace specular::host::SHADE_KERNEL_NS

#pragma GCC diagnostic pop
