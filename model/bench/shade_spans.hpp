// SPDX-License-Identifier: Apache-2.0
// Cross-span shading: every pixel of MANY spans per call, for scenes whose spans are 1-2
// pixels long (meshes), where a call per span costs more than its pixels. Used by
// scene_bench (model/bench/scene_bench.cpp); docs/system.md explains the measurement.
//
// Every method works in three stages over a batch of spans, in span order, and writes the
// pixels of span s at out[P_s .. P_s + l_s], P_s = sum over earlier spans of (l + 1):
//   1. per span, a loop over spans (vectorized by the compiler): the span's constants;
//   2. expansion: per span, 8 lanes of the values that are LINEAR in the pixel index i
//      (one or more 8-wide stores per span; the next span's stores start where this span's
//      pixels end and overwrite the surplus lanes), into an L1/L2-resident buffer;
//   3. per pixel, full vectors across span boundaries: the expensive function.
// So a span of 1 pixel costs one pass of stage 2, never a vector of stage 3 with one lane used.
// Builds: x86-64 baseline (shade_spans.cpp), AVX2 + FMA (shade_spans_avx2.cpp), AVX-512
// (shade_spans_avx512.cpp: the setup's automatic path uses AVX-512 where the CPU has it, so
// scene_bench can compare the methods at one instruction set, AVX2 or AVX-512).
//
//   DeviceShader::shade  the device method of model/reference/span_shade.hpp (device_span)
//                        from the register codes of host::setup_batch: stage 1 decodes psi0,
//                        dpsi (device::angle_value) and C (device::c_value) and scales the
//                        angles by a(n); stage 2 writes u_i = a psi0 + i a dpsi and C; stage 3
//                        is device_span's C cos^k(u) (the same polynomial and powering chain,
//                        model/reference/span_shade_kernel.inl), for each run of spans with one k.
//                        Same float arithmetic as device_span, so the same accuracy.
//   shade_phong          per-pixel (Blinn-)Phong in float: N_i = lerp(N1, N2, i/l), normalized,
//                        c = N_i . H_i, C c^n. Constant H (directional light and orthographic
//                        camera): stage 2 writes N_i . H and |N_i|^2, which are linear and
//                        quadratic in i (the same numbers as lerping N: the algebra of the dot
//                        product). Per-pixel H (point light or perspective camera): stage 2
//                        writes N_i and the perspective-correct surface point P_i as a numerator
//                        and a denominator (raster.hpp span_point); stage 3 forms L and V from
//                        P_i, H = normalize(L + V) and c. Powers: SLEEF Sleef_powf8_u10avx2
//                        (SimdPath::avx2) or libm powf per pixel (SimdPath::scalar); an AVX-512
//                        build with Sleef_powf16_u10avx512f (shade_phong_avx512).
//   shade_pow_cos        the scalar reference: C std::pow(std::cos(psi_i), n) in double from the
//                        register codes, pow_cos_span per span.
#pragma once

#include "device_model.hpp"
#include "raster.hpp"
#include "scanline_setup.hpp"
#include "scene.hpp"
#include "setup_batch.hpp"
#include "span_shade.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace specular::host {

// Pixels of a register batch: sum of (len + 1).
size_t pixel_count(const RegisterBatch& regs);

// The device method over a batch of register codes. Construct once (per Format): it builds
// the plans of n = 1..1000 (device_span_plan, about 30 ms the first time in a process).
class DeviceShader {
 public:
  explicit DeviceShader(const device::Format& f);
  // out must hold pixel_count(regs) floats. A span whose n code is 0 or above 1000 is dark
  // (as the device); len above 2047 throws std::invalid_argument.
  void shade(const RegisterBatch& regs, float* out, SimdPath path = SimdPath::automatic) const;
  // The same kernels built for AVX-512 (stage 3 16 floats wide); throws std::runtime_error
  // when cpu_has_avx512() is false. Same pixels as shade() with AVX2.
  void shade_avx512(const RegisterBatch& regs, float* out) const;

  // Per n code (0 .. 2^n_bits - 1): a(n) and k(n) of device_span_plan; invalid codes
  // (0, above 1000) have a = 0 and k = 1 and make the span dark.
  struct Tables {
    std::vector<double> a, a_scaled;  // a, and a 2^-angle_frac (u = a_scaled * angle code)
    std::vector<double> c_scale;      // 2^-c_frac, 0 for invalid codes (C = c_scale * c code)
    std::vector<int32_t> k;
    bool narrow = true;               // angle_bits <= 32: codes converted through int32
    float cut = 0;                    // float(pi/2): a >= 1 for every plan, so device_span's cut
  };
  const Tables& tables() const { return t_; }

 private:
  Tables t_;
};

// The per-pixel Phong inputs of a batch of spans, float, structure of arrays; built from the
// raster before timing (what a renderer holds per span: end normals, end points), in one
// order with the device's SpanBatch. Spans are grouped; within a group the light and the
// camera are the same, so the halfway vector is either constant per span (H = the span's h)
// or computed per pixel from the surface point.
struct PhongGroup {
  size_t begin = 0, end = 0;  // span range
  bool constant_h = true;     // directional light and orthographic camera
  bool point_light = false;   // light: position (point) or unit direction towards the light
  bool perspective = false;   // viewer: camera position (perspective) or unit direction to it
  std::array<float, 3> light{0, 0, 1}, viewer{0, 0, 1};
};
struct PhongSpans {
  std::vector<float> n1x, n1y, n1z, n2x, n2y, n2z;  // end normals (need not be unit)
  std::vector<float> hx, hy, hz;                    // unit H of the span (constant-H groups)
  std::vector<float> p1x, p1y, p1z, p2x, p2y, p2z;  // surface points at the end pixels
  std::vector<float> w1, w2;                        // their view depths (1: orthographic)
  std::vector<float> n, scale;                      // exponent, C = Is ks s(n)
  std::vector<int32_t> l;
  std::vector<PhongGroup> groups;

  size_t size() const { return l.size(); }
  size_t pixels() const;
  void push_back(const ScanlineInput& in, const glm::dvec3& p1, const glm::dvec3& p2, double w1, double w2);
};
// From a rasterized scene: spans in the given order; a new group wherever the light changes.
PhongSpans phong_spans(const Scene& scene, const std::vector<Span>& spans);
// Synthetic spans (host::random_spans*): one constant-H group, H = each span's h1.
PhongSpans phong_spans(const std::vector<ScanlineInput>& spans);

// SimdPath::avx2 (or automatic on an AVX2 CPU): SLEEF powf8; SimdPath::scalar: libm powf.
void shade_phong(const PhongSpans& spans, float* out, SimdPath path = SimdPath::automatic);
// AVX-512 (stage 3 16 floats wide, SLEEF Sleef_powf16_u10avx512f); throws std::runtime_error
// when cpu_has_avx512() is false.
void shade_phong_avx512(const PhongSpans& spans, float* out);

// AVX-512 F, DQ and VL: what setup_batch's automatic path takes when present (span_shade.hpp).
using specular::cpu_has_avx512;

// C cos^n(psi_i) in double from the register codes (pow_cos_span per span); out must hold
// pixel_count(regs) doubles.
void shade_pow_cos(const RegisterBatch& regs, const device::Format& f, double* out);

// The order both methods see the spans of a scene in: by light, then material (a renderer
// draws material by material), then the flat spans (is_flat: every one-pixel span) before
// the others, each in raster order (y, x). Stable. A rasterizer knows a span is flat when it
// emits it, so handing those over together costs it nothing; the batched setup then takes
// them by its flat kernel (docs/system.md#what-is-timed).
std::vector<Span> order_for_shading(const std::vector<Span>& spans);

namespace detail {
// The two compiled variants (shade_spans.cpp: x86-64 baseline; shade_spans_avx2.cpp).
void device_shade_baseline(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out);
void device_shade_avx2(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out);
void phong_shade_scalar(const PhongSpans& s, float* out);
void phong_shade_avx2(const PhongSpans& s, float* out);
void device_shade_avx512(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out);
void phong_shade_avx512(const PhongSpans& s, float* out);
}  // namespace detail

}  // namespace specular::host
