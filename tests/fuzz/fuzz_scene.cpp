// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the scene JSON loader (model/scene/scene.hpp, format in scenes/README.md).
// Contract under test: for any bytes, parse_scene either returns a scene that satisfies
// the loader's documented limits or throws SceneError. Any other exception, a crash, a
// sanitizer report or a hang is a bug.
//
// `model` meshes read files, and fuzzed JSON can name any path (/dev/zero, a FIFO, a
// large file). The target therefore parses as if the scene file were in FUZZ_MODEL_DIR
// (tests/fuzz/models/: a few tiny committed models, see tests/fuzz/README.md) and allows
// the loader only paths directly inside that directory (SceneOptions::model_file_allowed
// sees the lexically normalized path that is opened): relative names reach the tiny
// models, absent names the missing-file error, everything else is refused as SceneError.
#include "scene.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#ifndef FUZZ_MODEL_DIR
#error "FUZZ_MODEL_DIR must name tests/fuzz/models (set in tests/fuzz/CMakeLists.txt)"
#endif

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}

bool model_file_allowed(const std::string& resolved) {
  static const std::filesystem::path dir = std::filesystem::path(FUZZ_MODEL_DIR).lexically_normal();
  const std::filesystem::path p(resolved);
  const std::filesystem::path name = p.filename();
  return !name.empty() && name != "." && name != ".." && p.parent_path() == dir;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  static const std::string scene_path = std::string(FUZZ_MODEL_DIR) + "/fuzz.json";
  specular::SceneOptions options;
  options.model_file_allowed = model_file_allowed;
  try {
    const specular::Scene s = specular::parse_scene(text, scene_path, options);
    require(s.width >= 1 && s.width <= specular::kMaxImageSize);
    require(s.height >= 1 && s.height <= specular::kMaxImageSize);
    for (const auto& m : s.meshes) {
      require(m.material >= 0 && static_cast<size_t>(m.material) < s.materials.size());
      require(m.normals.size() == m.positions.size());
      for (const auto& t : m.triangles)
        for (int v : t) require(v >= 0 && static_cast<size_t>(v) < m.positions.size());
      if (m.kind == "model") {  // model/scene/model_file.hpp: finite points, unit normals, triangles
        require(!m.triangles.empty());
        for (const auto& p : m.positions) require(finite(p));
        for (const auto& n : m.normals) require(finite(n) && std::abs(glm::length(n) - 1.0) < 1e-9);
      }
    }
    for (const auto& mat : s.materials) require(std::isfinite(mat.n) && std::isfinite(mat.ks) && std::isfinite(mat.norm));
  } catch (const specular::SceneError&) {
    // a rejected scene: the documented outcome for bad input
  }
  return 0;
}
