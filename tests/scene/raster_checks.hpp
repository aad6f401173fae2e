// SPDX-License-Identifier: Apache-2.0
// What the scene tests check of every rasterized scene (test_repo_scenes.cpp for the listed
// scenes, test_model_files.cpp for the model-file scenes): every triangle rasterized, each
// span a non-empty row piece inside the image, the spans of one light disjoint.
#pragma once

#include "raster.hpp"
#include "scene.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace specular::test {

// per_span(span) runs on each span after its checks (the caller's own checks and sums).
template <class PerSpan>
void check_spans(const Scene& s, const Raster& r, PerSpan per_span) {
  CHECK(r.stats.triangles == s.triangle_count());
  CHECK(r.stats.triangles_dropped == 0);
  REQUIRE(r.spans.size() > 0);
  std::vector<int> count(static_cast<size_t>(s.width) * s.height * s.lights.size(), 0);
  for (const Span& sp : r.spans) {
    REQUIRE(sp.y >= 0);
    REQUIRE(sp.y < s.height);
    REQUIRE(sp.x_start >= 0);
    REQUIRE(sp.x_end < s.width);
    REQUIRE(sp.x_start <= sp.x_end);
    for (int x = sp.x_start; x <= sp.x_end; ++x)
      ++count[(static_cast<size_t>(sp.light) * s.height + sp.y) * s.width + x];
    per_span(sp);
  }
  CHECK(*std::max_element(count.begin(), count.end()) == 1);
}

}  // namespace specular::test
