// SPDX-License-Identifier: Apache-2.0
// Generated meshes: analytic normals, exact surfaces, closed topology, areas.
#include "scene.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

using namespace specular;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using glm::dvec3;

namespace {

// Edge -> number of triangles using it (undirected).
std::map<std::pair<int, int>, int> edge_use(const Mesh& m) {
  std::map<std::pair<int, int>, int> e;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++e[{std::min(a, b), std::max(a, b)}];
    }
  return e;
}

double total_area(const Mesh& m) {
  double a = 0;
  for (const auto& t : m.triangles)
    a += 0.5 * glm::length(glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
  return a;
}

}  // namespace

TEST_CASE("sphere: vertices on the sphere, normals unit and radial, closed surface", "[scene][mesh]") {
  const int t = GENERATE(3, 8, 25);
  const dvec3 c{0.3, -1.2, 2.0};
  const double r = 1.7;
  const dvec3 axis = GENERATE(dvec3{0, 1, 0}, dvec3{1, 2, 3});
  const Mesh m = make_sphere(c, r, t, axis);
  REQUIRE(m.positions.size() == m.normals.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    CHECK_THAT(glm::length(m.normals[i]), WithinAbs(1.0, 1e-14));
    CHECK_THAT(glm::length(m.positions[i] - c), WithinRel(r, 1e-13));
    const dvec3 analytic = (m.positions[i] - c) / glm::length(m.positions[i] - c);
    CHECK(glm::length(m.normals[i] - analytic) < 1e-13);
  }
  // Watertight: every edge in exactly two triangles; Euler characteristic 2.
  const auto edges = edge_use(m);
  for (const auto& [e, n] : edges) CHECK(n == 2);
  CHECK(static_cast<long>(m.positions.size()) - static_cast<long>(edges.size()) +
            static_cast<long>(m.triangles.size()) == 2);
  // Inscribed polyhedron: area below 4 pi r^2 and converging to it.
  const double sphere_area = 4 * std::numbers::pi * r * r;
  CHECK(total_area(m) < sphere_area);
  if (t == 25) CHECK(total_area(m) > 0.99 * sphere_area);
  // Outward winding: (b - a) x (c - a) points away from the centre.
  for (const auto& tri : m.triangles) {
    const dvec3 nrm = glm::cross(m.positions[tri[1]] - m.positions[tri[0]], m.positions[tri[2]] - m.positions[tri[0]]);
    const dvec3 centroid = (m.positions[tri[0]] + m.positions[tri[1]] + m.positions[tri[2]]) / 3.0;
    CHECK(glm::dot(nrm, centroid - c) > 0);
  }
}

TEST_CASE("torus: vertices on the torus, normals unit and analytic, closed surface of genus 1", "[scene][mesh]") {
  const int t = GENERATE(3, 12, 40);
  const dvec3 c{1, 2, -3};
  const double R = 2.0, r = 0.6;
  const dvec3 axis = glm::normalize(dvec3{0.2, 1.0, 0.4});
  const Mesh m = make_torus(c, R, r, t, axis);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const dvec3 p = m.positions[i] - c;
    // Independent closed form: the nearest point of the core circle is R times the
    // unit radial direction of p's projection onto the torus plane.
    const dvec3 planar = p - glm::dot(p, axis) * axis;
    const dvec3 core = R * glm::normalize(planar);
    CHECK_THAT(glm::length(p - core), WithinRel(r, 1e-12));
    const dvec3 analytic = glm::normalize(p - core);
    CHECK_THAT(glm::length(m.normals[i]), WithinAbs(1.0, 1e-14));
    CHECK(glm::length(m.normals[i] - analytic) < 1e-12);
  }
  const auto edges = edge_use(m);
  for (const auto& [e, n] : edges) CHECK(n == 2);
  CHECK(static_cast<long>(m.positions.size()) - static_cast<long>(edges.size()) +
            static_cast<long>(m.triangles.size()) == 0);
  if (t == 40) CHECK_THAT(total_area(m), WithinRel(4 * std::numbers::pi * std::numbers::pi * R * r, 0.01));
}

TEST_CASE("plane: flat, constant normal, area su * sv", "[scene][mesh]") {
  const int t = GENERATE(1, 2, 7);
  const dvec3 c{1, 2, 3}, nrm = glm::normalize(dvec3{0, 1, 0.2});
  const Mesh m = make_plane(c, nrm, {1, 0.5, 0}, 6.0, 4.0, t);
  CHECK(m.triangles.size() == 2u * t * t);
  for (size_t i = 0; i < m.positions.size(); ++i) {
    CHECK_THAT(glm::dot(m.positions[i] - c, nrm), WithinAbs(0.0, 1e-13));
    CHECK(glm::length(m.normals[i] - nrm) < 1e-15);
  }
  CHECK_THAT(total_area(m), WithinRel(24.0, 1e-12));
  // The tangent is made orthogonal to the normal; the first cell edge runs along it.
  const dvec3 e = glm::normalize(m.positions[1] - m.positions[0]);
  CHECK_THAT(glm::dot(e, nrm), WithinAbs(0.0, 1e-14));
  const dvec3 tan = glm::normalize(dvec3{1, 0.5, 0} - glm::dot(dvec3{1, 0.5, 0}, nrm) * nrm);
  CHECK(glm::length(e - tan) < 1e-13);
}
