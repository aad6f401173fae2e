// SPDX-License-Identifier: Apache-2.0
// Scanline rasterizer: scene -> spans of visible pixels, ready for the scanline setup.
//
// Fill rule (top-left, pixel centres at integer coordinates, y downwards): a pixel
// centre belongs to a triangle when it is strictly inside, or exactly on a left edge
// or on a horizontal top edge; right and bottom edges are excluded. Vertices are
// snapped to 1/256 pixel and every edge crossing is computed with exact integer
// arithmetic, so two triangles sharing an edge (same vertex coordinates) never leave
// a crack and never cover a pixel twice.
//
// Visibility: a z-buffer resolves the nearest triangle per pixel (first triangle wins
// on an exact tie). Spans contain ONLY visible pixels: a triangle's row run is split
// wherever another triangle is in front. No back-face culling (closed meshes are
// resolved by the depth test; open surfaces such as planes are two-sided).
// There is no near-plane clipping: a triangle with a vertex closer than camera.near
// (perspective) or outside a +-2^20 pixel guard band is dropped and counted.
//
// One span is emitted per (visible run, light): the device evaluates one light per
// pass and the image is the sum over lights.
#pragma once

#include "scanline_setup.hpp"
#include "scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace specular {

struct Span {
  int y = 0;
  int x_start = 0;  // first pixel centre
  int x_end = 0;    // last pixel centre (inclusive): l = x_end - x_start
  ScanlineInput setup_in;  // n1/n2 and h1/he at the pixel centres x_start and x_end; Is, ks, norm, n, l
  int material = 0;
  int light = 0;
  int mesh = 0;
  int triangle = 0;  // index within the mesh
  // For the per-pixel truth: surface points at the two end pixels and their view
  // depths. Screen-space parameter t = i / l maps to the surface point
  //   P(t) = ((1-t) p1/w1 + t p2/w2) / ((1-t)/w1 + t/w2)     (perspective-correct;
  // w1 = w2 = 1 for an orthographic camera).
  glm::dvec3 p1{0}, p2{0};
  double w1 = 1.0, w2 = 1.0;

  int length() const { return x_end - x_start; }  // l
  int pixels() const { return x_end - x_start + 1; }
};

struct RasterStats {
  size_t triangles = 0;           // in the scene
  size_t triangles_dropped = 0;   // near plane / guard band
  size_t triangles_degenerate = 0;  // zero screen area
  size_t covered_pixels = 0;      // distinct visible pixels
  size_t spans = 0;               // all lights
  size_t shaded_pixels = 0;       // sum of (l + 1) over spans
  int max_l = 0;
  size_t spans_l0 = 0, spans_l1 = 0;
};

struct Raster {
  int width = 0, height = 0;
  std::vector<Span> spans;  // sorted by (light, y, x_start)
  RasterStats stats;
};

// Screen-space position of a world point plus its view depth (distance along the
// viewing direction).
struct ScreenPoint {
  double x = 0, y = 0;  // pixel units, centres at integers
  double depth = 0;
};
ScreenPoint project(const Camera& cam, int width, int height, const glm::dvec3& p);

// Scans one screen-space triangle with the fill rule above, clipped to the image
// [0, width) x [0, height). Calls emit(y, x_first, x_last) for each non-empty row run
// (both ends inclusive). Returns false when the triangle was not drawn (degenerate or
// outside the guard band).
bool scan_triangle(const std::array<glm::dvec2, 3>& v, int width, int height,
                   const std::function<void(int y, int x_first, int x_last)>& emit);

Raster rasterize(const Scene& scene);

// Unit halfway vector at surface point p for light `light`; zero vector when
// L = -V (|L + V| = 0).
glm::dvec3 halfway(const Scene& scene, int light, const glm::dvec3& p);

// Surface point of pixel i (0..l) of a span (perspective-correct along the span).
glm::dvec3 span_point(const Span& s, int i);

// The shading normal of pixel i (0..l) of a span: N = normalize(lerp(n1, n2, i/l)) (screen-linear,
// as the device's t = i/l); the zero vector where the end normals cancel (undefined: shade 0).
glm::dvec3 pixel_normal(const Span& s, int i);

// Per-pixel Phong-shading truth for pixel i of a span: normalized-lerp normal
// N = pixel_normal(s, i) and the TRUE
// halfway vector at that pixel's surface point (point light and perspective camera
// included). Returns Is * ks * norm * max(0, N.H)^n.
double pixel_truth(const Scene& scene, const Span& s, int i);

}  // namespace specular
