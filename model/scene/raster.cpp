// SPDX-License-Identifier: Apache-2.0
// Scanline rasterizer; the rules are documented in raster.hpp.
#include "raster.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace specular {

using glm::dvec2;
using glm::dvec3;

namespace {

constexpr int64_t kSub = 256;             // sub-pixel steps per pixel (8 bits)
constexpr double kGuard = 1048576.0;      // 2^20 pixels: keeps every product below 2^60

// floor / ceil of a / b for b > 0, exact for negative a.
int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

struct Fixed {
  int64_t x, y;
};

// First pixel column whose centre is at or right of edge a->b (Ya < Yb) on row Y.
// The crossing is Xa + (Y - Ya) (Xb - Xa) / (Yb - Ya) sub-pixel units; exact rational.
int64_t edge_ceil(const Fixed& a, const Fixed& b, int64_t Y) {
  const int64_t dy = b.y - a.y;
  const int64_t num = a.x * dy + (Y - a.y) * (b.x - a.x);
  return ceil_div(num, kSub * dy);
}

}  // namespace

ScreenPoint project(const Camera& cam, int width, int height, const dvec3& p) {
  const dvec3 d = p - cam.position;
  const double vx = glm::dot(d, cam.right());
  const double vy = glm::dot(d, cam.true_up());
  const double vz = glm::dot(d, cam.forward());
  const double aspect = static_cast<double>(width) / height;
  double nx, ny;
  if (cam.type == CameraType::orthographic) {
    nx = vx / (0.5 * cam.height * aspect);
    ny = vy / (0.5 * cam.height);
  } else {
    const double f = 1.0 / std::tan(0.5 * cam.fov_y_deg * std::numbers::pi / 180.0);
    nx = f * vx / (vz * aspect);
    ny = f * vy / vz;
  }
  // NDC [-1, 1] covers the pixel squares, so pixel centres sit at integers 0..size-1.
  return {(nx + 1.0) * 0.5 * width - 0.5, (1.0 - ny) * 0.5 * height - 0.5, vz};
}

bool scan_triangle(const std::array<dvec2, 3>& v, int width, int height,
                   const std::function<void(int, int, int)>& emit) {
  std::array<Fixed, 3> f{};
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(v[i].x) <= kGuard && std::abs(v[i].y) <= kGuard)) return false;  // also rejects NaN
    f[i] = {std::llround(v[i].x * kSub), std::llround(v[i].y * kSub)};
  }
  // Sort by (y, x): the order is canonical, so a shared edge is always walked the same way.
  std::sort(f.begin(), f.end(), [](const Fixed& a, const Fixed& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  const Fixed &v0 = f[0], &v1 = f[1], &v2 = f[2];
  const int64_t cross = (v1.x - v0.x) * (v2.y - v0.y) - (v1.y - v0.y) * (v2.x - v0.x);
  if (cross == 0) return false;
  const bool middle_left = cross < 0;  // v1 lies left of the long edge v0 -> v2

  // Rows whose centre Y satisfies Y0 <= Y < Y2 (top inclusive, bottom exclusive).
  const int64_t y_first = std::max<int64_t>(ceil_div(v0.y, kSub), 0);
  const int64_t y_last = std::min<int64_t>(ceil_div(v2.y, kSub) - 1, height - 1);
  for (int64_t y = y_first; y <= y_last; ++y) {
    const int64_t Y = y * kSub;
    const int64_t x_long = edge_ceil(v0, v2, Y);
    const int64_t x_short = Y < v1.y ? edge_ceil(v0, v1, Y) : edge_ceil(v1, v2, Y);
    // Left edge inclusive (first centre at or right of it), right edge exclusive.
    int64_t xa = middle_left ? x_short : x_long;
    int64_t xb = (middle_left ? x_long : x_short) - 1;
    xa = std::max<int64_t>(xa, 0);
    xb = std::min<int64_t>(xb, width - 1);
    if (xa <= xb) emit(static_cast<int>(y), static_cast<int>(xa), static_cast<int>(xb));
  }
  return true;
}

dvec3 halfway(const Scene& scene, int light, const dvec3& p) {
  const dvec3 h = scene.lights[light].to_light(p) + scene.camera.to_viewer(p);
  const double len = glm::length(h);
  if (!(len > 1e-300)) return dvec3(0.0);
  return h / len;
}

dvec3 span_point(const Span& s, int i) {
  const int l = s.length();
  if (l == 0) return s.p1;
  const double t = static_cast<double>(i) / l;
  const double a = (1.0 - t) / s.w1, b = t / s.w2;
  return (a * s.p1 + b * s.p2) / (a + b);
}

dvec3 pixel_normal(const Span& s, int i) {
  const int l = s.length();
  const double t = l == 0 ? 0.0 : static_cast<double>(i) / l;
  const dvec3 nl = (1.0 - t) * s.setup_in.n1 + t * s.setup_in.n2;
  const double nlen = glm::length(nl);
  if (!(nlen > 0.0)) return dvec3(0.0);  // opposite end normals cancel: undefined
  return nl / nlen;
}

double pixel_truth(const Scene& scene, const Span& s, int i) {
  const dvec3 n = pixel_normal(s, i);
  if (n == dvec3(0.0)) return 0.0;  // undefined normal: shade 0
  const dvec3 h = halfway(scene, s.light, span_point(s, i));
  const double c = glm::dot(n, h);
  if (!(c > 0.0)) return 0.0;
  return s.setup_in.is * s.setup_in.ks * s.setup_in.norm * std::pow(c, s.setup_in.n);
}

namespace {

// One triangle prepared for per-pixel attribute evaluation.
struct PreparedTri {
  int mesh = 0, tri = 0;
  std::array<dvec2, 3> s{};   // snapped screen positions (exactly what scan_triangle uses)
  std::array<double, 3> w{};  // view depths (1 for orthographic: plain affine interpolation)
  std::array<double, 3> depth{};  // view depths (for the z-buffer)
  double area2 = 0;           // twice the signed screen area
  bool perspective = false;
};

// Screen-space barycentric coordinates of point (x, y).
std::array<double, 3> barycentric(const PreparedTri& t, double x, double y) {
  const auto& s = t.s;
  const double b0 = ((s[1].x - x) * (s[2].y - y) - (s[2].x - x) * (s[1].y - y)) / t.area2;
  const double b1 = ((s[2].x - x) * (s[0].y - y) - (s[0].x - x) * (s[2].y - y)) / t.area2;
  return {b0, b1, 1.0 - b0 - b1};
}

// Perspective-correct weights (affine ones for orthographic).
std::array<double, 3> surface_weights(const PreparedTri& t, double x, double y) {
  auto b = barycentric(t, x, y);
  if (!t.perspective) return b;
  double sum = 0;
  for (int k = 0; k < 3; ++k) sum += (b[k] /= t.w[k]);
  for (auto& bk : b) bk /= sum;
  return b;
}

// View depth at a pixel: affine for orthographic, 1/depth affine for perspective.
double pixel_depth(const PreparedTri& t, double x, double y) {
  const auto b = barycentric(t, x, y);
  if (!t.perspective) return b[0] * t.depth[0] + b[1] * t.depth[1] + b[2] * t.depth[2];
  return 1.0 / (b[0] / t.depth[0] + b[1] / t.depth[1] + b[2] / t.depth[2]);
}

}  // namespace

Raster rasterize(const Scene& scene) {
  Raster r;
  r.width = scene.width;
  r.height = scene.height;
  const int W = scene.width, H = scene.height;
  const bool persp = scene.camera.type == CameraType::perspective;

  // Project every vertex once so that shared vertices have identical screen coordinates.
  std::vector<PreparedTri> tris;
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const Mesh& m = scene.meshes[mi];
    std::vector<ScreenPoint> sp(m.positions.size());
    for (size_t k = 0; k < m.positions.size(); ++k) sp[k] = project(scene.camera, W, H, m.positions[k]);
    for (size_t ti = 0; ti < m.triangles.size(); ++ti) {
      ++r.stats.triangles;
      PreparedTri t;
      t.mesh = static_cast<int>(mi);
      t.tri = static_cast<int>(ti);
      t.perspective = persp;
      bool ok = true;
      for (int k = 0; k < 3; ++k) {
        const ScreenPoint& p = sp[m.triangles[ti][k]];
        if (persp && !(p.depth >= scene.camera.near)) ok = false;
        if (!(std::abs(p.x) <= kGuard && std::abs(p.y) <= kGuard)) ok = false;
        if (!ok) break;
        t.s[k] = {std::llround(p.x * kSub) / static_cast<double>(kSub), std::llround(p.y * kSub) / static_cast<double>(kSub)};
        t.w[k] = persp ? p.depth : 1.0;
        t.depth[k] = p.depth;
      }
      if (!ok) {
        ++r.stats.triangles_dropped;
        continue;
      }
      t.area2 = (t.s[1].x - t.s[0].x) * (t.s[2].y - t.s[0].y) - (t.s[1].y - t.s[0].y) * (t.s[2].x - t.s[0].x);
      if (t.area2 == 0.0) {
        ++r.stats.triangles_degenerate;
        continue;
      }
      tris.push_back(t);
    }
  }

  // Pass 1: z-buffer, nearest triangle id per pixel.
  std::vector<double> zbuf(static_cast<size_t>(W) * H, std::numeric_limits<double>::infinity());
  std::vector<int> idbuf(static_cast<size_t>(W) * H, -1);
  for (size_t id = 0; id < tris.size(); ++id) {
    const PreparedTri& t = tris[id];
    scan_triangle(t.s, W, H, [&](int y, int xa, int xb) {
      for (int x = xa; x <= xb; ++x) {
        const double z = pixel_depth(t, x, y);
        const size_t k = static_cast<size_t>(y) * W + x;
        if (z < zbuf[k]) {
          zbuf[k] = z;
          idbuf[k] = static_cast<int>(id);
        }
      }
    });
  }
  for (int v : idbuf) r.stats.covered_pixels += v >= 0;

  // Pass 2: each triangle's row runs, split into maximal runs where it is visible.
  auto emit_span = [&](const PreparedTri& t, int y, int xa, int xb) {
    const Mesh& m = scene.meshes[t.mesh];
    const auto& tri = m.triangles[t.tri];
    const Material& mat = scene.materials[m.material];
    auto attributes = [&](int x, dvec3& p, dvec3& n, double& w) {
      const auto b = surface_weights(t, x, y);
      p = b[0] * m.positions[tri[0]] + b[1] * m.positions[tri[1]] + b[2] * m.positions[tri[2]];
      n = glm::normalize(b[0] * m.normals[tri[0]] + b[1] * m.normals[tri[1]] + b[2] * m.normals[tri[2]]);
      w = persp ? pixel_depth(t, x, y) : 1.0;
    };
    Span s;
    s.y = y;
    s.x_start = xa;
    s.x_end = xb;
    s.material = m.material;
    s.mesh = t.mesh;
    s.triangle = t.tri;
    attributes(xa, s.p1, s.setup_in.n1, s.w1);
    attributes(xb, s.p2, s.setup_in.n2, s.w2);
    s.setup_in.ks = mat.ks;
    s.setup_in.norm = mat.norm;
    s.setup_in.n = mat.n;
    s.setup_in.l = xb - xa;
    for (size_t li = 0; li < scene.lights.size(); ++li) {
      s.light = static_cast<int>(li);
      s.setup_in.is = scene.lights[li].intensity;
      s.setup_in.h1 = halfway(scene, s.light, s.p1);
      s.setup_in.he = halfway(scene, s.light, s.p2);
      r.spans.push_back(s);
    }
  };
  for (size_t id = 0; id < tris.size(); ++id) {
    const PreparedTri& t = tris[id];
    scan_triangle(t.s, W, H, [&](int y, int xa, int xb) {
      const int* row = &idbuf[static_cast<size_t>(y) * W];
      int x = xa;
      while (x <= xb) {
        if (row[x] != static_cast<int>(id)) {
          ++x;
          continue;
        }
        int e = x;
        while (e + 1 <= xb && row[e + 1] == static_cast<int>(id)) ++e;
        emit_span(t, y, x, e);
        x = e + 1;
      }
    });
  }

  std::sort(r.spans.begin(), r.spans.end(), [](const Span& a, const Span& b) {
    if (a.light != b.light) return a.light < b.light;
    if (a.y != b.y) return a.y < b.y;
    return a.x_start < b.x_start;
  });
  r.stats.spans = r.spans.size();
  for (const Span& s : r.spans) {
    r.stats.shaded_pixels += s.pixels();
    r.stats.max_l = std::max(r.stats.max_l, s.length());
    r.stats.spans_l0 += s.length() == 0;
    r.stats.spans_l1 += s.length() == 1;
  }
  return r;
}

}  // namespace specular
