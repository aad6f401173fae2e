// libFuzzer target: the scene JSON loader (model/scene/scene.hpp, format in scenes/README.md).
// Contract under test: for any bytes, parse_scene either returns a scene that satisfies
// the loader's documented limits or throws SceneError. Any other exception, a crash, a
// sanitizer report or a hang is a bug.
#include "scene.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const specular::Scene s = specular::parse_scene(text, "fuzz.json");
    require(s.width >= 1 && s.width <= specular::kMaxImageSize);
    require(s.height >= 1 && s.height <= specular::kMaxImageSize);
    for (const auto& m : s.meshes) {
      require(m.material >= 0 && static_cast<size_t>(m.material) < s.materials.size());
      require(m.normals.size() == m.positions.size());
      for (const auto& t : m.triangles)
        for (int v : t) require(v >= 0 && static_cast<size_t>(v) < m.positions.size());
    }
    for (const auto& mat : s.materials) require(std::isfinite(mat.n) && std::isfinite(mat.ks) && std::isfinite(mat.norm));
  } catch (const specular::SceneError&) {
    // a rejected scene: the documented outcome for bad input
  }
  return 0;
}
