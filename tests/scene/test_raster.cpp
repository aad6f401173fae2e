// SPDX-License-Identifier: Apache-2.0
// Fill rule, depth test and span attributes of the scanline rasterizer.
#include "raster.hpp"
#include "scanline_setup.hpp"
#include "scene.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace specular;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using glm::dvec2;
using glm::dvec3;

namespace {

struct Canvas {
  int w, h;
  std::vector<int> count;
  Canvas(int w_, int h_) : w(w_), h(h_), count(static_cast<size_t>(w_) * h_, 0) {}
  int& at(int x, int y) { return count[static_cast<size_t>(y) * w + x]; }
  void draw(const std::array<dvec2, 3>& t) {
    scan_triangle(t, w, h, [&](int y, int xa, int xb) {
      REQUIRE(xa <= xb);
      for (int x = xa; x <= xb; ++x) ++at(x, y);
    });
  }
  long total() const {
    long s = 0;
    for (int c : count) s += c;
    return s;
  }
  int max() const {
    int m = 0;
    for (int c : count) m = std::max(m, c);
    return m;
  }
};

// Snap to the rasterizer's 1/256 grid so the test knows the exact geometry.
dvec2 snap(dvec2 p) { return {std::round(p.x * 256) / 256, std::round(p.y * 256) / 256}; }

// Signed edge function of p against a->b.
double edge(dvec2 a, dvec2 b, dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

}  // namespace

TEST_CASE("a rectangle split into two triangles covers every pixel exactly once", "[scene][raster][fill]") {
  // Corners off and on pixel centres. With centres at integers, the top-left rule
  // covers centres in the half-open box [x0, x1) x [y0, y1).
  struct Box {
    double x0, y0, x1, y1;
  };
  const Box b = GENERATE(Box{10.3, 20.7, 50.6, 60.2}, Box{8, 8, 24, 40}, Box{-3.5, 2.25, 70.75, 30.5},
                         Box{5.0, 5.5, 5.75, 40.0});
  const bool other_diagonal = GENERATE(false, true);
  const dvec2 p00{b.x0, b.y0}, p10{b.x1, b.y0}, p01{b.x0, b.y1}, p11{b.x1, b.y1};
  Canvas c(64, 64);
  if (!other_diagonal) {
    c.draw({p00, p10, p11});
    c.draw({p00, p11, p01});
  } else {
    c.draw({p00, p10, p01});
    c.draw({p10, p11, p01});
  }
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      const bool inside = x >= b.x0 && x < b.x1 && y >= b.y0 && y < b.y1;
      INFO("pixel " << x << "," << y);
      CHECK(c.at(x, y) == (inside ? 1 : 0));
    }
  if (b.x0 == 8) CHECK(c.total() == 16 * 32);  // integer corners: count = area
}

TEST_CASE("a fan of triangles around a vertex: no crack, no double cover", "[scene][raster][fill]") {
  const dvec2 centre = GENERATE(dvec2{32, 32}, dvec2{32.5, 31.25}, dvec2{31.7, 32.3});
  const int n = GENERATE(3, 8, 17, 64);
  const bool reverse = GENERATE(false, true);
  const double radius = 20.0, phase = 0.1;
  std::vector<dvec2> ring;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / n;
    ring.push_back(snap(centre + radius * dvec2{std::cos(a), std::sin(a)}));
  }
  const dvec2 ctr = snap(centre);
  Canvas c(64, 64);
  for (int k = 0; k < n; ++k) {
    const dvec2 a = ring[k], b = ring[(k + 1) % n];
    if (reverse)
      c.draw({ctr, b, a});
    else
      c.draw({ctr, a, b});
  }
  CHECK(c.max() == 1);
  double area = 0, perimeter = 0;
  for (int k = 0; k < n; ++k) {
    const dvec2 a = ring[k], b = ring[(k + 1) % n];
    area += 0.5 * edge(ctr, a, b);
    perimeter += glm::length(b - a);
  }
  // The polygon is convex and counter-clockwise in (x, y): edge() > 0 inside.
  for (int y = 0; y < c.h; ++y)
    for (int x = 0; x < c.w; ++x) {
      double m = 1e300;
      for (int k = 0; k < n; ++k) m = std::min(m, edge(ring[k], ring[(k + 1) % n], dvec2(x, y)));
      INFO("pixel " << x << "," << y);
      if (m > 1e-9) CHECK(c.at(x, y) == 1);
      if (m < -1e-9) CHECK(c.at(x, y) == 0);
    }
  CHECK(std::abs(c.total() - area) < perimeter);
}

TEST_CASE("a jittered triangle mesh covers its interior exactly once", "[scene][raster][fill]") {
  // (g+1)^2 vertices on a jittered grid, some exactly on pixel centres; the interior
  // box [4, 60) x [4, 60) is inside the hull whatever the jitter.
  const unsigned seed = GENERATE(1u, 2u, 3u);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-2.0, 2.0);
  const int g = 12;
  const double cell = 60.0 / g;
  std::vector<dvec2> v;
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) {
      const bool border = i == 0 || j == 0 || i == g || j == g;
      dvec2 p{2 + i * cell, 2 + j * cell};
      if (!border) p += dvec2{jitter(rng), jitter(rng)};
      if ((i + j) % 3 == 0) p = {std::round(p.x), std::round(p.y)};  // on a pixel centre
      v.push_back(snap(p));
    }
  auto id = [&](int i, int j) { return v[static_cast<size_t>(j * (g + 1) + i)]; };
  Canvas c(64, 64);
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      if ((i + j) % 2) {
        c.draw({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        c.draw({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        c.draw({id(i, j), id(i + 1, j), id(i, j + 1)});
        c.draw({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  CHECK(c.max() == 1);
  for (int y = 4; y < 60; ++y)
    for (int x = 4; x < 60; ++x) {
      INFO("pixel " << x << "," << y);
      CHECK(c.at(x, y) == 1);
    }
  CHECK(c.total() == 60 * 60);  // the hull is the square [2, 62) x [2, 62)
}

TEST_CASE("clipping to the image equals the in-image part of an unclipped scan", "[scene][raster][fill]") {
  const std::array<dvec2, 3> t{dvec2{-20.3, -5.1}, dvec2{50.7, 10.2}, dvec2{10.1, 70.6}};
  Canvas small(40, 40), big(200, 200);
  small.draw(t);
  // Shift by an integer offset: the snapped geometry shifts exactly.
  big.draw({t[0] + dvec2{100, 100}, t[1] + dvec2{100, 100}, t[2] + dvec2{100, 100}});
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) CHECK(small.at(x, y) == big.at(x + 100, y + 100));
}

TEST_CASE("degenerate triangles cover nothing", "[scene][raster][fill]") {
  Canvas c(32, 32);
  CHECK_FALSE(scan_triangle({dvec2{1, 1}, dvec2{10, 10}, dvec2{20, 20}}, 32, 32, [](int, int, int) { FAIL(); }));
  CHECK_FALSE(scan_triangle({dvec2{1, 1}, dvec2{1, 1}, dvec2{20, 5}}, 32, 32, [](int, int, int) { FAIL(); }));
  CHECK_FALSE(scan_triangle({dvec2{NAN, 1}, dvec2{1, 1}, dvec2{20, 5}}, 32, 32, [](int, int, int) { FAIL(); }));
}

namespace {

// Orthographic camera on +z looking at the origin: world [-1, 1]^2 fills a 64x64 image,
// pixel centre (x, y) is world ((x + 0.5) / 32 - 1, 1 - (y + 0.5) / 32).
Scene ortho_scene() {
  Scene s;
  s.name = "test";
  s.width = s.height = 64;
  s.camera.type = CameraType::orthographic;
  s.camera.position = {0, 0, 10};
  s.camera.look_at = {0, 0, 0};
  s.camera.up = {0, 1, 0};
  s.camera.height = 2.0;
  s.materials.push_back({"m", 10.0, 1.0, 1.0});
  Light l;
  l.direction = glm::normalize(dvec3{0.3, 0.2, 1});
  s.lights.push_back(l);
  return s;
}

dvec2 pixel_world(int x, int y) { return {(x + 0.5) / 32.0 - 1.0, 1.0 - (y + 0.5) / 32.0}; }

Mesh triangle(dvec3 a, dvec3 b, dvec3 c, dvec3 na = {0, 0, 1}, dvec3 nb = {0, 0, 1}, dvec3 nc = {0, 0, 1}) {
  Mesh m;
  m.kind = "triangles";
  m.positions = {a, b, c};
  m.normals = {glm::normalize(na), glm::normalize(nb), glm::normalize(nc)};
  m.triangles = {{0, 1, 2}};
  return m;
}

// Owner mesh per pixel from the spans of light 0; -2 marks a pixel in two spans.
std::vector<int> owners(const Raster& r) {
  std::vector<int> own(static_cast<size_t>(r.width) * r.height, -1);
  for (const Span& s : r.spans) {
    if (s.light != 0) continue;
    for (int x = s.x_start; x <= s.x_end; ++x) {
      int& o = own[static_cast<size_t>(s.y) * r.width + x];
      o = o == -1 ? s.mesh : -2;
    }
  }
  return own;
}

double min_edge(dvec2 a, dvec2 b, dvec2 c, dvec2 p) {
  // Orientation-independent signed distance-like measure: > 0 strictly inside.
  const double s = edge(a, b, c) > 0 ? 1.0 : -1.0;
  return std::min({s * edge(a, b, p), s * edge(b, c, p), s * edge(c, a, p)});
}

}  // namespace

TEST_CASE("depth test: the nearer of two overlapping triangles owns the overlap", "[scene][raster][depth]") {
  Scene s = ortho_scene();
  const bool near_first = GENERATE(false, true);
  // A: large at z = 0; B: smaller at z = 0.5 (nearer to the camera at z = 10).
  const Mesh a = triangle({-0.9, -0.9, 0}, {0.9, -0.8, 0}, {-0.2, 0.9, 0});
  const Mesh b = triangle({-0.5, -0.3, 0.5}, {0.7, 0.1, 0.5}, {0.0, 0.6, 0.5});
  s.meshes = near_first ? std::vector<Mesh>{b, a} : std::vector<Mesh>{a, b};
  const int ia = near_first ? 1 : 0, ib = 1 - ia;
  const Raster r = rasterize(s);
  const auto own = owners(r);
  long in_a = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const dvec2 p = pixel_world(x, y);
      const double ea = min_edge({-0.9, -0.9}, {0.9, -0.8}, {-0.2, 0.9}, p);
      const double eb = min_edge({-0.5, -0.3}, {0.7, 0.1}, {0.0, 0.6}, p);
      const int o = own[static_cast<size_t>(y) * 64 + x];
      INFO("pixel " << x << "," << y);
      CHECK(o != -2);
      if (eb > 1e-9) CHECK(o == ib);
      else if (eb < -1e-9 && ea > 1e-9) CHECK(o == ia);
      else if (eb < -1e-9 && ea < -1e-9) CHECK(o == -1);
      in_a += o == ia;
    }
  CHECK(in_a > 0);
  // Spans contain only visible pixels: A's spans around B are split, so A has more
  // spans than rows.
  int a_spans = 0, a_rows_lo = 64, a_rows_hi = -1;
  for (const Span& sp : r.spans)
    if (sp.mesh == ia) {
      ++a_spans;
      a_rows_lo = std::min(a_rows_lo, sp.y);
      a_rows_hi = std::max(a_rows_hi, sp.y);
    }
  CHECK(a_spans > a_rows_hi - a_rows_lo + 1);
}

TEST_CASE("depth test per pixel: interpenetrating triangles swap along their intersection", "[scene][raster][depth]") {
  Scene s = ortho_scene();
  // A tilted: z = 0.4 x; B flat at z = 0. A is nearer where x > 0.
  s.meshes = {triangle({-0.9, -0.9, -0.36}, {0.9, -0.9, 0.36}, {0.0, 0.9, 0.0}),
              triangle({-0.9, 0.9, 0}, {0.9, 0.9, 0}, {0.0, -0.9, 0})};
  const auto own = owners(rasterize(s));
  int checked = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const dvec2 p = pixel_world(x, y);
      const bool ina = min_edge({-0.9, -0.9}, {0.9, -0.9}, {0.0, 0.9}, p) > 1e-9;
      const bool inb = min_edge({-0.9, 0.9}, {0.9, 0.9}, {0.0, -0.9}, p) > 1e-9;
      if (!(ina && inb) || std::abs(p.x) < 1e-9) continue;
      CHECK(own[static_cast<size_t>(y) * 64 + x] == (p.x > 0 ? 0 : 1));
      ++checked;
    }
  CHECK(checked > 200);
}

TEST_CASE("span ends carry the interpolated normal, surface point and halfway vector", "[scene][raster][span]") {
  Scene s = ortho_scene();
  const dvec3 A{-0.8, -0.7, 0.1}, B{0.85, -0.5, -0.2}, C{-0.1, 0.8, 0.3};
  const dvec3 NA = glm::normalize(dvec3{-0.5, -0.4, 1}), NB = glm::normalize(dvec3{0.6, -0.2, 1}),
              NC = glm::normalize(dvec3{0.0, 0.7, 1});
  s.meshes = {triangle(A, B, C, NA, NB, NC)};
  const Raster r = rasterize(s);
  REQUIRE(r.spans.size() > 30);
  const dvec3 H = glm::normalize(s.lights[0].direction + dvec3{0, 0, 1});  // V = +z (orthographic)
  for (const Span& sp : r.spans) {
    for (int end = 0; end < 2; ++end) {
      const int x = end ? sp.x_end : sp.x_start;
      // Independent barycentrics of the pixel centre in the world xy plane.
      const dvec2 p = pixel_world(x, sp.y);
      const double d = (B.x - A.x) * (C.y - A.y) - (C.x - A.x) * (B.y - A.y);
      const double wb = ((p.x - A.x) * (C.y - A.y) - (C.x - A.x) * (p.y - A.y)) / d;
      const double wc = ((B.x - A.x) * (p.y - A.y) - (p.x - A.x) * (B.y - A.y)) / d;
      const double wa = 1 - wb - wc;
      const dvec3 n = glm::normalize(wa * NA + wb * NB + wc * NC);
      const dvec3 pt = wa * A + wb * B + wc * C;
      // Vertices are snapped to 1/256 pixel: attributes agree to that level.
      CHECK(glm::length((end ? sp.setup_in.n2 : sp.setup_in.n1) - n) < 2e-3);
      CHECK(glm::length((end ? sp.p2 : sp.p1) - pt) < 2e-3);
      CHECK(glm::length((end ? sp.setup_in.he : sp.setup_in.h1) - H) < 1e-14);
    }
    CHECK(sp.setup_in.l == sp.x_end - sp.x_start);
    CHECK(sp.setup_in.n == 10.0);
    CHECK(glm::length(sp.setup_in.n1) == Approx(1.0).epsilon(1e-14));
    // Directional light + orthographic viewer: H is constant, so the scene truth must
    // agree with the scanline model's own truth (which lerps H).
    for (int i = 0; i <= sp.length(); ++i)
      CHECK_THAT(pixel_truth(s, sp, i), WithinAbs(phong_truth(sp.setup_in, i), 1e-13));
  }
}

TEST_CASE("perspective: span pixels map to surface points on their pixel rays", "[scene][raster][span]") {
  Scene s = ortho_scene();
  s.camera.type = CameraType::perspective;
  s.camera.position = {0.3, 0.5, 3};
  s.camera.fov_y_deg = 60;
  const dvec3 A{-1.5, -1.0, -1.0}, B{1.5, -1.2, 0.5}, C{0.2, 1.4, -2.0};
  s.meshes = {triangle(A, B, C)};
  Light pl;
  pl.type = LightType::point;
  pl.position = {1, 2, 1};
  s.lights = {pl};
  const Raster r = rasterize(s);
  REQUIRE(r.spans.size() > 20);
  const dvec3 nrm = glm::normalize(glm::cross(B - A, C - A));
  int checked = 0;
  for (size_t k = 0; k < r.spans.size(); k += 7) {
    const Span& sp = r.spans[k];
    for (int i = 0; i <= sp.length(); i += 3) {
      const dvec3 p = span_point(sp, i);
      // On the triangle's plane (within the 1/256-pixel vertex snap) ...
      CHECK(std::abs(glm::dot(p - A, nrm)) < 5e-3);
      // ... and on the ray through the pixel centre.
      const ScreenPoint q = project(s.camera, s.width, s.height, p);
      CHECK_THAT(q.x, WithinAbs(sp.x_start + i, 0.01));  // vertex snap: 1/256 px
      CHECK_THAT(q.y, WithinAbs(sp.y, 0.01));
      // H at the end pixels is the true halfway vector there.
      const dvec3 h = glm::normalize(glm::normalize(pl.position - p) + glm::normalize(s.camera.position - p));
      if (i == 0) CHECK(glm::length(h - sp.setup_in.h1) < 1e-12);
      ++checked;
    }
  }
  CHECK(checked > 20);
}
