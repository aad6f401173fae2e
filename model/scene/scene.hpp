// SPDX-License-Identifier: Apache-2.0
// Scenes: meshes, materials, lights, camera and image size, loaded from JSON
// (format documented in scenes/README.md).
//
// Conventions: right-handed world space; the camera looks from `position` towards
// `look_at`. Screen space has pixel centres at integer coordinates (x, y),
// x = 0..width-1 to the right, y = 0..height-1 downwards.
#pragma once

#include "brdf.hpp"
#include "scanline_setup.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace specular {

// A bad scene file: the message names the file, the field and what was expected.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The reflectance functions a material may name in "brdf" (scenes/README.md#colour): a shape
// of model/reference/brdf.hpp as a function of the angle between N and H, and whether its
// energy normalization (ModelEvaluator::own_norm) multiplies it. Only the colour reference
// (compose.hpp) evaluates it; the device and the grey images always compute cos^n.
struct BrdfChoice {
  std::string name;   // as written in the scene file
  Model model = Model::blinn;
  bool normalized = false;
};
const std::vector<BrdfChoice>& brdf_choices();  // the first is the default, "blinn_phong"

struct Material {
  std::string name;
  double n = 1.0;     // specular exponent, [1, 1000]
  double ks = 1.0;    // specular coefficient, [0, 1]
  double norm = 1.0;  // normalization s(n) applied through C (1: none)
  // Colour (linear light, channels r, g, b; compose.hpp):
  glm::dvec3 diffuse{0.0};                // Lambert reflectance, each channel in [0, 1]
  std::optional<glm::dvec3> specular{};   // specular colour, each channel in [0, 1]; none: ks
  glm::dvec3 emission{0.0};               // emitted light, each channel in [0, 1000]
  BrdfChoice brdf = brdf_choices().front();

  // The specular colour: `specular`, or [ks, ks, ks] when the scene gives none.
  glm::dvec3 specular_colour() const { return specular ? *specular : glm::dvec3(ks); }
};

enum class LightType { directional, point };

struct Light {
  LightType type = LightType::directional;
  glm::dvec3 direction{0, 0, 1};  // directional: unit vector from the surface TOWARDS the light
  glm::dvec3 position{0, 0, 0};   // point light position
  double intensity = 1.0;         // Is
  std::optional<glm::dvec3> color{};  // colour of the light, each channel in [0, 1000]; none: Is

  // The light's colour (compose.hpp): `color`, or [Is, Is, Is] when the scene gives none.
  glm::dvec3 colour() const { return color ? *color : glm::dvec3(intensity); }

  // Unit vector from surface point p towards the light.
  glm::dvec3 to_light(const glm::dvec3& p) const;
};

enum class CameraType { orthographic, perspective };

struct Camera {
  CameraType type = CameraType::orthographic;
  glm::dvec3 position{0, 0, 10};
  glm::dvec3 look_at{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double fov_y_deg = 45.0;  // perspective: full vertical field of view
  double height = 2.0;      // orthographic: world-space height of the view
  double near = 1e-3;       // perspective: triangles with a vertex closer than this are dropped

  // Orthonormal camera frame (right, true up, forward = towards look_at).
  glm::dvec3 right() const;
  glm::dvec3 true_up() const;
  glm::dvec3 forward() const;

  // Unit vector from surface point p towards the viewer.
  glm::dvec3 to_viewer(const glm::dvec3& p) const;
};

struct Mesh {
  std::string kind;  // "triangles", "sphere", "torus", "plane", "model"
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // unit, one per position
  std::vector<std::array<int, 3>> triangles;
  int material = 0;  // index into Scene::materials
};

struct Scene {
  std::string name;  // file stem
  std::string path;
  int width = 256, height = 256;
  Camera camera;
  std::vector<Material> materials;
  std::vector<Light> lights;
  std::vector<Mesh> meshes;
  glm::dvec3 ambient{0.0};  // ambient light (compose.hpp), each channel in [0, 1000]

  size_t triangle_count() const;
};

// Limits enforced by the loader. The span counter of the device holds l <= kMaxLen
// (scanline_setup.hpp), so an image row may hold at most kMaxLen + 1 pixels.
inline constexpr int kMaxImageSize = kMaxLen + 1;
inline constexpr int kMaxTessellation = 1024;
inline constexpr double kMaxReflectance = 1.0;  // diffuse and specular colour channels: [0, 1]
inline constexpr double kMaxRadiance = 1000.0;  // emission, ambient and light colour channels: [0, 1000]

Scene load_scene(const std::string& path);               // throws SceneError
Scene parse_scene(const std::string& json_text, const std::string& path_for_messages);

// What the loader may read besides the scene file itself: the files of `model` meshes
// (model_file.hpp). Their paths are resolved against the directory of the scene path
// (`path_for_messages` for parse_scene) and lexically normalized; that resolved path is
// what `model_file_allowed` sees and what is opened. Empty: every path is allowed. The
// fuzz target (tests/fuzz/fuzz_scene.cpp) allows one directory of tiny models only, so
// fuzzed JSON cannot make it read arbitrary files.
struct SceneOptions {
  std::function<bool(const std::string& resolved_path)> model_file_allowed;
};
Scene load_scene(const std::string& path, const SceneOptions& options);
Scene parse_scene(const std::string& json_text, const std::string& path_for_messages, const SceneOptions& options);

// Mesh generators (indexed, seams share vertices so adjacent triangles share
// exact coordinates: no cracks). Normals are the analytic surface normals.
// Sphere: 2*t segments in longitude, t rings in latitude, poles on `axis`.
Mesh make_sphere(const glm::dvec3& center, double radius, int t, const glm::dvec3& axis = {0, 1, 0});
// Torus around `axis`: 2*t segments around the axis, t around the tube.
Mesh make_torus(const glm::dvec3& center, double major_radius, double minor_radius, int t,
                const glm::dvec3& axis = {0, 1, 0});
// Rectangle of size (su along `tangent`, sv along normal x tangent), t x t cells, normal constant.
Mesh make_plane(const glm::dvec3& center, const glm::dvec3& normal, const glm::dvec3& tangent,
                double su, double sv, int t);

}  // namespace specular
