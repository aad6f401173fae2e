// SPDX-License-Identifier: Apache-2.0
// Geometry spans for the tests of the hardware setup (docs/setup_hw.md): the hard cases of
// docs/scanline_setup.md#hard-cases on the geometry span interface, named, and random spans
// with vectors of every length the interface carries. Shared by the golden model's test
// (tests/model/test_setup_fixed.cpp) and the RTL's (tests/rtl/test_setup.cpp).
#pragma once

#include "coefficients.hpp"
#include "device_model.hpp"
#include "geo_span.hpp"
#include "scanline_setup.hpp"
#include "setup_batch.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace specular::geo_cases {

using device::GeoSpan;
using device::GeoVec;

inline const device::GeoFormat kGeo;
inline const device::Format kFmt;

struct Hard {
  std::string name;
  GeoSpan g;
};

inline GeoVec code(double x, double y, double z) { return device::quantize_vec({x, y, z}, kGeo); }

inline std::vector<Hard> hard_cases() {
  std::vector<Hard> h;
  auto add = [&](const std::string& name, auto edit) {
    ScanlineInput in;
    in.n1 = glm::normalize(glm::dvec3{0.1, 0.2, 1.0});
    in.n2 = glm::normalize(glm::dvec3{0.3, -0.1, 1.0});
    in.h1 = glm::normalize(glm::dvec3{0.15, 0.05, 1.0});
    in.he = in.h1;
    in.n = 50;
    in.l = 20;
    GeoSpan g = device::quantize_geo(in, kGeo, kFmt, static_cast<uint32_t>(h.size()));
    edit(g);
    h.push_back({name, g});
  };
  const int32_t vmax = static_cast<int32_t>(kGeo.vec_max()), vmin = static_cast<int32_t>(kGeo.vec_min());
  add("ordinary", [](GeoSpan&) {});
  add("N1 = N2", [](GeoSpan& s) { s.n2 = s.n1; });
  add("N1 = N2, H1 = He (flat: gamma 0)", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1; });
  add("N1 = 2 N2, H1 = 3 He (flat, non-unit)", [](GeoSpan& s) {
    s.n1 = {1000, 2000, 10000}, s.n2 = {2000, 4000, 20000}, s.h1 = {3000, 1500, 30000}, s.he = {1000, 500, 10000};
  });
  add("gamma tiny (one code)", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1, s.he[0] += 1; });
  add("gamma tiny, long span", [](GeoSpan& s) { s.n2 = s.n1, s.he = s.h1, s.he[1] -= 1, s.len = 2047, s.n = 1000; });
  add("cos t1 < 0", [](GeoSpan& s) { s.h1 = s.he = code(1, 0, -0.2); });
  add("cos t1 = 0", [](GeoSpan& s) { s.n1 = s.n2 = code(0, 0, 1), s.h1 = s.he = code(1, 0, 0); });
  add("N1 = -N2", [](GeoSpan& s) { s.n2 = {-s.n1[0], -s.n1[1], -s.n1[2]}; });
  add("N1 = -3 N2", [](GeoSpan& s) { s.n1 = {3000, -6000, 9000}, s.n2 = {-1000, 2000, -3000}; });
  add("N1 = -N2 nearly (one code)", [](GeoSpan& s) { s.n2 = {-s.n1[0] + 1, -s.n1[1], -s.n1[2]}; });
  add("N1 = -N2, He along N1", [](GeoSpan& s) { s.n2 = {-s.n1[0], -s.n1[1], -s.n1[2]}, s.he = s.n1; });
  add("H2 = -H1 (N1 = N2)", [](GeoSpan& s) {
    s.n1 = s.n2 = code(0, 0, 1), s.h1 = code(0.6, 0, 0.8), s.he = {-s.h1[0], -s.h1[1], -s.h1[2]};
  });
  add("H2 = -H1 (a quarter turn)", [](GeoSpan& s) {
    s.n1 = {0, 0, 40000}, s.n2 = {40000, 0, 0}, s.h1 = {0, 30000, 40000}, s.he = {-40000, -30000, 0};
  });
  add("L = -V: H1 zero", [](GeoSpan& s) { s.h1 = {0, 0, 0}; });
  add("L = -V: He zero", [](GeoSpan& s) { s.he = {0, 0, 0}; });
  add("non-unit vectors", [](GeoSpan& s) {
    s.n1 = code(0.03, 0.06, 0.3), s.n2 = code(0.45, -0.15, 1.5), s.h1 = code(0.27, 0.09, 1.8), s.he = code(0.0015, 0.0005, 0.01);
  });
  add("tiny vectors (a few codes)", [](GeoSpan& s) { s.n1 = {0, 0, 1}, s.n2 = {1, 0, 2}, s.h1 = {1, 1, 3}, s.he = {0, 1, 1}; });
  add("tiny vectors, flat", [](GeoSpan& s) { s.n1 = s.n2 = {1, -1, 1}, s.h1 = s.he = {0, 0, 1}; });
  add("maximum vectors", [vmax, vmin](GeoSpan& s) {
    s.n1 = {vmax, vmax, vmax}, s.n2 = {vmin, vmax, vmax}, s.h1 = {vmax, vmin / 2, vmax}, s.he = {vmin, vmin, vmax};
  });
  add("maximum and tiny", [vmax](GeoSpan& s) { s.n1 = {vmax, 0, vmax}, s.n2 = {1, 0, 1}, s.h1 = {0, 1, 1}, s.he = {vmax, vmax, vmax}; });
  add("zero N1", [](GeoSpan& s) { s.n1 = {0, 0, 0}; });
  add("zero N2", [](GeoSpan& s) { s.n2 = {0, 0, 0}; });
  add("zero N1 and H1", [](GeoSpan& s) { s.n1 = {0, 0, 0}, s.h1 = {0, 0, 0}; });
  add("n = 0", [](GeoSpan& s) { s.n = 0; });
  add("n = 1001", [](GeoSpan& s) { s.n = kMaxN + 1; });
  add("n = 1023", [](GeoSpan& s) { s.n = 1023; });
  add("l = 0", [](GeoSpan& s) { s.len = 0; });
  add("l = 2047", [](GeoSpan& s) { s.len = kMaxLen; });
  add("l = 2047, n = 1000", [](GeoSpan& s) { s.len = kMaxLen, s.n = 1000; });
  for (uint32_t n : {1u, 2u, 3u, 4u, 5u, 7u, 10u, 14u, 999u, 1000u})
    add("n = " + std::to_string(n), [n](GeoSpan& s) { s.n = n; });
  add("psi crosses 0", [](GeoSpan& s) {
    s.n1 = code(0, 0, 1), s.n2 = code(0.2, 0, 1), s.h1 = s.he = code(0.1, 0, 1), s.n = 1000, s.len = 400;
  });
  add("psi beyond pi/2", [](GeoSpan& s) {
    s.n1 = code(0, 0, 1), s.n2 = code(1, 0, 0), s.h1 = s.he = code(-1, 0, 0.3), s.len = 300, s.n = 1;
  });
  add("scale 0", [](GeoSpan& s) { s.scale = 0; });
  add("scale at the maximum, A = 1", [](GeoSpan& s) { s.n2 = s.n1, s.h1 = s.he = s.n1, s.scale = 65535; });
  add("scale at the maximum, n = 1", [](GeoSpan& s) { s.scale = 65535, s.n = 1; });
  return h;
}

// Spans of the interface: host::random_spans quantized, with vectors of every length the
// interface carries (unit, shortened like a rasterizer's lerped normals, tiny, up to the
// maximum) and a share of flat spans.
inline std::vector<GeoSpan> random_geo_spans(size_t count, uint64_t seed) {
  const std::vector<ScanlineInput> in = host::random_spans(count, seed);
  std::mt19937_64 rng(seed ^ 0x5e7f13edULL);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<GeoSpan> out;
  out.reserve(count);
  for (size_t i = 0; i < in.size(); ++i) {
    ScanlineInput s = in[i];
    if (u01(rng) < 0.3) s.n2 = s.n1, s.he = s.h1;
    for (glm::dvec3* v : {&s.n1, &s.n2, &s.h1, &s.he}) {
      const double k = u01(rng);
      const double f = k < 0.4 ? 1.0 : k < 0.7 ? 0.5 + 0.5 * u01(rng) : k < 0.85 ? std::exp2(-16.0 + 12.0 * u01(rng))
                                                                                  : 1.0 + 0.73 * u01(rng);
      *v *= f;
    }
    out.push_back(device::quantize_geo(s, kGeo, kFmt, static_cast<uint32_t>(i)));
  }
  return out;
}

// Spans the hard cases do not reach: He a few codes from -H1, N2 a few codes from -N1, and
// tiny chords between codes at the largest C (docs/setup_hw.md#the-contract). The setup's
// model test and its RTL block test run them.
inline std::vector<GeoSpan> near_degenerate_spans() {
  std::vector<GeoSpan> v;
  for (int d : {0, 1, 2, 3, 5, 10, 30, 300, 3000})
    for (int y : {1, 7}) {
      GeoSpan g;
      g.n1 = g.n2 = {0, 0, 65536};
      g.h1 = {131071, y, 0};
      g.he = {-131071 + d, -y, 0};
      g.n = 100, g.len = 100, g.scale = 30000;
      v.push_back(g);
    }
  for (int d : {0, 1, 3, 10, 100, 300, 1000, 3000, 10000}) {
    GeoSpan g;
    g.n1 = {12000, -5000, 60000};
    g.n2 = {-12000 + d, 5000, -60000};
    g.h1 = {3000, 2000, 65000};
    g.he = {-2000, 1000, 65000};
    g.n = 200, g.len = 40, g.scale = 50000;
    v.push_back(g);
  }
  for (int d : {1, 2, 3, 5}) {
    GeoSpan g;
    g.n1 = g.n2 = g.h1 = {1000, 2000, 65000};
    g.he = {1000 + d, 2000 - d, 65000};
    g.n = 1000, g.len = 2047, g.scale = 65535;
    v.push_back(g);
  }
  return v;
}

}  // namespace specular::geo_cases
