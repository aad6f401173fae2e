// SPDX-License-Identifier: Apache-2.0
// Spans of the geometry interface for the Phong golden model's tests (test_phong_model.cpp,
// test_phong_cross.cpp): random unit vectors and a span quantized from double vectors.
#pragma once

#include "phong_model.hpp"
#include "scanline_setup.hpp"

#include <glm/geometric.hpp>

#include <random>

namespace specular::test {

inline glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v);
  }
}

// A span of the interface from double vectors (quantized by the interface's quantizer).
inline device::GeoSpan span_of(const device::PhongFormat& f, glm::dvec3 n1, glm::dvec3 n2, glm::dvec3 h1,
                               glm::dvec3 he, int n, int l, double scale = 1.0, uint32_t tag = 0) {
  ScanlineInput in;
  in.n1 = n1;
  in.n2 = n2;
  in.h1 = h1;
  in.he = he;
  in.n = n;
  in.l = l;
  in.is = scale;
  return device::quantize_geo(in, device::geo_format(f), device::c_format(f), tag);
}

}  // namespace specular::test
