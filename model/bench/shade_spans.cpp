// SPDX-License-Identifier: Apache-2.0
// Cross-span shaders (model/bench/shade_spans.hpp): tables, builders of the Phong inputs,
// run-time dispatch, the x86-64 baseline kernels and the scalar (libm powf) Phong stage 3.
#include "shade_spans.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#define SHADE_KERNEL_NS shade_baseline
#include "shade_spans_kernel.inl"
#undef SHADE_KERNEL_NS

namespace specular::host {

size_t pixel_count(const RegisterBatch& regs) {
  size_t p = 0;
  for (uint32_t l : regs.len) p += static_cast<size_t>(l) + 1;
  return p;
}

DeviceShader::DeviceShader(const device::Format& f) {
  // One code above every valid one, so that the kernel can clamp any code into the table.
  const int codes = std::max(1 << f.n_bits, f.max_n() + 2);
  t_.a.assign(codes, 0.0);
  t_.a_scaled.assign(codes, 0.0);
  t_.c_scale.assign(codes, 0.0);
  t_.k.assign(codes, 1);
  t_.narrow = f.angle_bits <= 32 && f.c_bits <= 31;
  t_.cut = static_cast<float>(std::numbers::pi / 2);
  for (int n = 1; n < codes && n <= f.max_n(); ++n) {
    const DeviceSpanPlan& p = device_span_plan(n);
    // device_span's cut is float(pi/2 min(1, a)); one cut for every span needs a >= 1,
    // which holds for every plan (k <= n).
    if (!(p.a >= 1.0)) throw std::logic_error("DeviceShader: a plan with a < 1");
    t_.a[n] = p.a;
    t_.a_scaled[n] = std::ldexp(p.a, -f.angle_frac);
    t_.c_scale[n] = std::ldexp(1.0, -f.c_frac);
    t_.k[n] = p.k;
  }
}

void DeviceShader::shade_avx512(const RegisterBatch& regs, float* out) const {
  if (!cpu_has_avx512()) throw std::runtime_error("DeviceShader::shade_avx512: this CPU lacks AVX-512 F/DQ/VL");
  detail::device_shade_avx512(t_, regs, out);
}

void shade_phong_avx512(const PhongSpans& spans, float* out) {
  if (!cpu_has_avx512()) throw std::runtime_error("shade_phong_avx512: this CPU lacks AVX-512 F/DQ/VL");
  detail::phong_shade_avx512(spans, out);
}

void DeviceShader::shade(const RegisterBatch& regs, float* out, SimdPath path) const {
  if (resolve(path) == SimdPath::avx2)
    detail::device_shade_avx2(t_, regs, out);
  else
    detail::device_shade_baseline(t_, regs, out);
}

size_t PhongSpans::pixels() const {
  size_t p = 0;
  for (int32_t v : l) p += static_cast<size_t>(v) + 1;
  return p;
}

void PhongSpans::push_back(const ScanlineInput& in, const glm::dvec3& p1, const glm::dvec3& p2, double wa,
                           double wb) {
  auto f = [](double v) { return static_cast<float>(v); };
  n1x.push_back(f(in.n1.x)), n1y.push_back(f(in.n1.y)), n1z.push_back(f(in.n1.z));
  n2x.push_back(f(in.n2.x)), n2y.push_back(f(in.n2.y)), n2z.push_back(f(in.n2.z));
  hx.push_back(f(in.h1.x)), hy.push_back(f(in.h1.y)), hz.push_back(f(in.h1.z));
  p1x.push_back(f(p1.x)), p1y.push_back(f(p1.y)), p1z.push_back(f(p1.z));
  p2x.push_back(f(p2.x)), p2y.push_back(f(p2.y)), p2z.push_back(f(p2.z));
  w1.push_back(f(wa)), w2.push_back(f(wb));
  n.push_back(f(in.n));
  scale.push_back(f(in.is * in.ks * in.norm));
  l.push_back(in.l);
}

PhongSpans phong_spans(const Scene& scene, const std::vector<Span>& spans) {
  PhongSpans s;
  const Camera& cam = scene.camera;
  const bool persp = cam.type == CameraType::perspective;
  for (size_t i = 0; i < spans.size(); ++i) {
    const Span& sp = spans[i];
    if (s.groups.empty() || i == 0 || spans[i - 1].light != sp.light) {
      if (!s.groups.empty()) s.groups.back().end = i;
      const Light& L = scene.lights.at(sp.light);
      PhongGroup g;
      g.begin = i;
      g.point_light = L.type == LightType::point;
      g.perspective = persp;
      g.constant_h = !g.point_light && !g.perspective;
      const glm::dvec3 lv = g.point_light ? L.position : glm::normalize(L.direction);
      const glm::dvec3 vv = persp ? cam.position : cam.to_viewer(glm::dvec3(0.0));
      g.light = {static_cast<float>(lv.x), static_cast<float>(lv.y), static_cast<float>(lv.z)};
      g.viewer = {static_cast<float>(vv.x), static_cast<float>(vv.y), static_cast<float>(vv.z)};
      s.groups.push_back(g);
    }
    s.push_back(sp.setup_in, sp.p1, sp.p2, sp.w1, sp.w2);
  }
  if (!s.groups.empty()) s.groups.back().end = spans.size();
  return s;
}

PhongSpans phong_spans(const std::vector<ScanlineInput>& spans) {
  PhongSpans s;
  for (const ScanlineInput& in : spans) s.push_back(in, glm::dvec3(0.0), glm::dvec3(0.0), 1.0, 1.0);
  PhongGroup g;
  g.end = spans.size();
  s.groups.push_back(g);
  return s;
}

void shade_phong(const PhongSpans& spans, float* out, SimdPath path) {
  if (resolve(path) == SimdPath::avx2)
    detail::phong_shade_avx2(spans, out);
  else
    detail::phong_shade_scalar(spans, out);
}

void shade_pow_cos(const RegisterBatch& regs, const device::Format& f, double* out) {
  size_t at = 0;
  for (size_t s = 0; s < regs.size(); ++s) {
    const bool valid = regs.n[s] >= 1 && static_cast<int>(regs.n[s]) <= f.max_n();
    const int len = static_cast<int>(regs.len[s]);
    pow_cos_span(valid ? regs.n[s] : 1.0, device::angle_value(regs.psi0[s], f), device::angle_value(regs.dpsi[s], f),
                 len, valid ? device::c_value(regs.c[s], f) : 0.0, out + at);
    at += static_cast<size_t>(len) + 1;
  }
}

std::vector<Span> order_for_shading(const std::vector<Span>& spans) {
  std::vector<Span> v = spans;
  std::stable_sort(v.begin(), v.end(), [](const Span& a, const Span& b) {
    if (a.light != b.light) return a.light < b.light;
    if (a.material != b.material) return a.material < b.material;
    return is_flat(a.setup_in) && !is_flat(b.setup_in);
  });
  return v;
}

namespace detail {

void device_shade_baseline(const DeviceShader::Tables& t, const RegisterBatch& regs, float* out) {
  shade_baseline::device_shade(t, regs, out);
}

namespace {

// Stage 3 of Phong with libm: c = N.H / |N| |H|, C powf(c, n) where c > 0.
inline float phong_pixel(float dot, float q, float n, float C) {
  const float c = dot / std::sqrt(q);
  return c > 0.0f ? C * std::pow(c, n) : 0.0f;
}

// Stage 3 of Phong in scalar code (phong_shade's Stage3).
struct ScalarPhong {
  static void constant(const shade_baseline::PhongBuffers& B, int count, float* o) {
    for (int i = 0; i < count; ++i) o[i] = phong_pixel(B.d[i], B.q[i], B.n[i], B.c[i]);
  }

  template <bool Point, bool Persp>
  static void pp(const shade_baseline::PhongBuffers& B, int count, const PhongGroup& g, float* out) {
    for (int i = 0; i < count; ++i) {
      const float r = 1.0f / B.den[i];
      const float px = B.px[i] * r, py = B.py[i] * r, pz = B.pz[i] * r;
      float lx = g.light[0], ly = g.light[1], lz = g.light[2];
      if constexpr (Point) {
        lx -= px, ly -= py, lz -= pz;
        const float s = 1.0f / std::sqrt(lx * lx + ly * ly + lz * lz);
        lx *= s, ly *= s, lz *= s;
      }
      float vx = g.viewer[0], vy = g.viewer[1], vz = g.viewer[2];
      if constexpr (Persp) {
        vx -= px, vy -= py, vz -= pz;
        const float s = 1.0f / std::sqrt(vx * vx + vy * vy + vz * vz);
        vx *= s, vy *= s, vz *= s;
      }
      const float hx = lx + vx, hy = ly + vy, hz = lz + vz;
      const float nx = B.nx[i], ny = B.ny[i], nz = B.nz[i];
      const float dot = nx * hx + ny * hy + nz * hz;
      const float q = (nx * nx + ny * ny + nz * nz) * (hx * hx + hy * hy + hz * hz);
      out[i] = phong_pixel(dot, q, B.n[i], B.c[i]);
    }
  }
};

}  // namespace

void phong_shade_scalar(const PhongSpans& s, float* out) { shade_baseline::phong_shade<ScalarPhong>(s, out); }

}  // namespace detail

}  // namespace specular::host
