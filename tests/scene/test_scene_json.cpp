// SPDX-License-Identifier: Apache-2.0
// Scene file errors name the file, the field and what was expected.
#include "scene.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace specular;

namespace {

// A valid scene; tests replace one piece of it.
const std::string kCamera =
    R"("camera": {"type": "orthographic", "position": [0, 0, 10], "look_at": [0, 0, 0], "height": 2})";
const std::string kMaterials = R"("materials": [{"name": "m", "n": 20, "ks": 0.5}])";
const std::string kLights = R"("lights": [{"type": "directional", "direction": [0, 0, 2], "intensity": 0.75}])";
const std::string kMeshes = R"("meshes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "tessellation": 8, "material": "m"}])";
const std::string kImage = R"("image": {"width": 64, "height": 48})";

std::string scene_text(const std::string& image = kImage, const std::string& camera = kCamera,
                       const std::string& materials = kMaterials, const std::string& lights = kLights,
                       const std::string& meshes = kMeshes) {
  std::string s = "{\n";
  for (const auto* part : {&image, &camera, &materials, &lights, &meshes})
    if (!part->empty()) s += (s.size() > 2 ? ",\n" : "") + *part;
  return s + "\n}\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "scenes/bad.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a valid scene parses into the values written in it", "[scene][json]") {
  const Scene s = parse_scene(scene_text(), "dir/my_scene.json");
  CHECK(s.name == "my_scene");
  CHECK(s.width == 64);
  CHECK(s.height == 48);
  CHECK(s.camera.type == CameraType::orthographic);
  CHECK(s.camera.height == 2.0);
  REQUIRE(s.materials.size() == 1);
  CHECK(s.materials[0].n == 20.0);
  CHECK(s.materials[0].ks == 0.5);
  CHECK(s.materials[0].norm == 1.0);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].type == LightType::directional);
  CHECK(s.lights[0].direction.z == 1.0);  // normalized from [0, 0, 2]
  CHECK(s.lights[0].intensity == 0.75);
  REQUIRE(s.meshes.size() == 1);
  // Sphere with t = 8: 2t segments, t rings -> 4 t (t - 1) triangles, 2t(t-1) + 2 vertices.
  CHECK(s.meshes[0].triangles.size() == 4u * 8 * 7);
  CHECK(s.meshes[0].positions.size() == 2u * 8 * 7 + 2);
}

TEST_CASE("colour fields: defaults keep the grey scene, given values are read", "[scene][json][colour]") {
  // Without colour fields: diffuse and emission 0, specular colour [ks, ks, ks], blinn_phong,
  // light colour [Is, Is, Is], ambient 0.
  const Scene g = parse_scene(scene_text(), "grey.json");
  CHECK(g.materials[0].diffuse == glm::dvec3(0.0));
  CHECK(g.materials[0].emission == glm::dvec3(0.0));
  CHECK_FALSE(g.materials[0].specular.has_value());
  CHECK(g.materials[0].specular_colour() == glm::dvec3(0.5));
  CHECK(g.materials[0].brdf.name == "blinn_phong");
  CHECK(g.materials[0].brdf.model == Model::blinn);
  CHECK_FALSE(g.materials[0].brdf.normalized);
  CHECK(g.lights[0].colour() == glm::dvec3(0.75));
  CHECK(g.ambient == glm::dvec3(0.0));

  const Scene c = parse_scene(
      scene_text(kImage, kCamera,
                 R"("materials": [{"name": "m", "n": 20, "ks": 0.5, "diffuse": [0.5, 0.25, 0], "specular": [1, 0, 0.125],
                                   "emission": [0, 0, 1000], "brdf": "f16"}])",
                 R"("lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 0.75, "color": [0, 2, 1000]},
                               {"type": "point", "position": [0, 0, 1], "intensity": 0.5, "color": [0, 0, 0]}])",
                 kMeshes + R"(, "ambient": [0.25, 0.5, 0])"),
      "colour.json");
  CHECK(c.materials[0].diffuse == glm::dvec3(0.5, 0.25, 0.0));
  CHECK(c.materials[0].specular_colour() == glm::dvec3(1.0, 0.0, 0.125));
  CHECK(c.materials[0].ks == 0.5);  // the grey images keep ks
  CHECK(c.materials[0].emission == glm::dvec3(0.0, 0.0, 1000.0));
  CHECK(c.materials[0].brdf.model == Model::f16);
  CHECK(c.materials[0].brdf.normalized);
  CHECK(c.lights[0].colour() == glm::dvec3(0.0, 2.0, 1000.0));
  CHECK(c.lights[0].intensity == 0.75);  // the grey images keep Is
  CHECK(c.lights[1].colour() == glm::dvec3(0.0));
  CHECK(c.ambient == glm::dvec3(0.25, 0.5, 0.0));
}

TEST_CASE("colour fields: every BRDF name parses into its shape of brdf.hpp", "[scene][json][colour]") {
  const struct {
    const char* name;
    Model model;
    bool normalized;
  } want[] = {{"blinn_phong", Model::blinn, false},        {"blinn_phong_normalized", Model::blinn, true},
              {"schlick", Model::schlick, false},           {"schlick_normalized", Model::schlick, true},
              {"schlick_mod", Model::schlick_mod, false},   {"schlick_mod_normalized", Model::schlick_mod, true},
              {"lyon", Model::lyon, false},                 {"lyon_normalized", Model::lyon, true},
              {"f16", Model::f16, true}};
  REQUIRE(brdf_choices().size() == std::size(want));
  for (const auto& w : want) {
    INFO(w.name);
    const Scene s = parse_scene(
        scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 20, "ks": 0.5, "brdf": ")" + std::string(w.name) + "\"}]"),
        "brdf.json");
    CHECK(s.materials[0].brdf.name == w.name);
    CHECK(s.materials[0].brdf.model == w.model);
    CHECK(s.materials[0].brdf.normalized == w.normalized);
  }
}

TEST_CASE("bad scene files: the message names file, field and expectation", "[scene][json]") {
  struct Case {
    std::string text, field, expected;
  };
  const std::vector<Case> cases = {
      {scene_text(""), "'image'", "missing"},
      {scene_text(R"("image": {"width": 0, "height": 48})"), "'image.width'", "an integer in [1, 2048]"},
      {scene_text(R"("image": {"width": 4096, "height": 48})"), "'image.width'", "an integer in [1, 2048]"},
      {scene_text(R"("image": {"width": 64.5, "height": 48})"), "'image.width'", "an integer"},
      {scene_text(kImage, R"("camera": {"type": "fisheye", "position": [0,0,1], "look_at": [0,0,0]})"), "'camera.type'",
       "one of \"orthographic\", \"perspective\""},
      {scene_text(kImage, R"("camera": {"type": "perspective", "position": [0,0,1], "look_at": [0,0,0], "fov_y_deg": 180})"),
       "'camera.fov_y_deg'", "a number in [1, 170]"},
      {scene_text(kImage, R"("camera": {"type": "orthographic", "position": [0,0,1], "look_at": [0,0,1], "height": 1})"),
       "'camera.look_at'", "different from camera.position"},
      {scene_text(kImage, R"("camera": {"type": "orthographic", "position": [0,0,1], "look_at": [0,0,0], "up": [0,0,5], "height": 1})"),
       "'camera.up'", "not parallel"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 2000, "ks": 0.5}])"), "'materials[0].n'",
       "a number in [1, 1000]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": "shiny"}])"), "'materials[0].ks'",
       "a number in [0, 1]"},
      {scene_text(kImage, kCamera, R"("materials": [])"), "'materials'", "at least 1 element"},
      {scene_text(kImage, kCamera, kMaterials, R"("lights": [{"type": "directional", "direction": [0, 0, 0], "intensity": 1}])"),
       "'lights[0].direction'", "not all zero"},
      {scene_text(kImage, kCamera, kMaterials, R"("lights": [{"type": "point", "intensity": 1}])"), "'lights[0].position'",
       "missing"},
      {scene_text(kImage, kCamera, kMaterials, R"("lights": [{"type": "spot", "intensity": 1}])"), "'lights[0].type'",
       "one of \"directional\", \"point\""},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "sphere", "center": [0,0,0], "radius": -1, "tessellation": 8, "material": "m"}])"),
       "'meshes[0].radius'", "a number in (0, "},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "sphere", "center": [0,0], "radius": 1, "tessellation": 8, "material": "m"}])"),
       "'meshes[0].center'", "an array of 3 finite numbers"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "tessellation": 2, "material": "m"}])"),
       "'meshes[0].tessellation'", "an integer in [3, 1024]"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "sphere", "center": [0,0,0], "radus": 1, "tessellation": 8, "material": "m"}])"),
       "'meshes[0].radus'", "unknown field"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "sphere", "center": [0,0,0], "radius": 1, "tessellation": 8, "material": "gold"}])"),
       "'meshes[0].material'", "the name of a material (\"m\")"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "torus", "center": [0,0,0], "major_radius": 1, "minor_radius": 2, "tessellation": 8, "material": "m"}])"),
       "'meshes[0].minor_radius'", "smaller than major_radius"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "triangles", "material": "m", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "normals": [[0,0,1],[0,0,1],[0,0,1]], "triangles": [[0,1,3]]}])"),
       "'meshes[0].triangles[0]'", "3 vertex indices in [0, 2]"},
      {scene_text(kImage, kCamera, kMaterials, kLights,
                  R"("meshes": [{"type": "triangles", "material": "m", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "normals": [[0,0,1],[0,0,1]], "triangles": [[0,1,2]]}])"),
       "'meshes[0].normals'", "one normal per vertex"},
      {"[1, 2, 3]", "'(top level)'", "an object"},
      // Colour (scenes/README.md#colour): negative, out of range, not three finite numbers, unknown BRDF.
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "diffuse": [0.5, -0.1, 0.2]}])"),
       "'materials[0].diffuse'", "an array of 3 finite numbers, each in [0, 1]"},
      {scene_text(kImage, kCamera,
                  R"("materials": [{"name": "a", "n": 5, "ks": 0.5}, {"name": "m", "n": 5, "ks": 0.5, "diffuse": [0.5, 0.2]}])"),
       "'materials[1].diffuse'", "an array of 3 finite numbers, each in [0, 1]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "specular": [0.5, 0.2, 0.1, 0.0]}])"),
       "'materials[0].specular'", "an array of 3 finite numbers, each in [0, 1]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "specular": [0.5, 1.5, 0.1]}])"),
       "'materials[0].specular'", "an array of 3 finite numbers, each in [0, 1]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "emission": [0, "red", 0]}])"),
       "'materials[0].emission'", "an array of 3 finite numbers, each in [0, 1000]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "emission": 0.5}])"),
       "'materials[0].emission'", "an array of 3 finite numbers, each in [0, 1000]"},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "brdf": "cook_torrance"}])"),
       "'materials[0].brdf'", "one of \"blinn_phong\", \"blinn_phong_normalized\", \"schlick\""},
      {scene_text(kImage, kCamera, R"("materials": [{"name": "m", "n": 5, "ks": 0.5, "brdf": 3}])"),
       "'materials[0].brdf'", "\"f16\""},
      {scene_text(kImage, kCamera, kMaterials,
                  R"("lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 1, "color": [1, -0.5, 1]}])"),
       "'lights[0].color'", "an array of 3 finite numbers, each in [0, 1000]"},
      {scene_text(kImage, kCamera, kMaterials,
                  R"("lights": [{"type": "point", "position": [0, 0, 1], "intensity": 1, "color": [1, 2000, 1]}])"),
       "'lights[0].color'", "an array of 3 finite numbers, each in [0, 1000]"},
      {scene_text(kImage, kCamera, kMaterials,
                  R"("lights": [{"type": "point", "position": [0, 0, 1], "intensity": 1, "colour": [1, 1, 1]}])"),
       "'lights[0].colour'", "unknown field, expected no field 'colour' (allowed: type position intensity color)"},
      {scene_text(kImage, kCamera, kMaterials, kLights, kMeshes + R"(, "ambient": [0.1, 0.1])"), "'ambient'",
       "an array of 3 finite numbers, each in [0, 1000]"},
      {scene_text(kImage, kCamera, kMaterials, kLights, kMeshes + R"(, "ambient": [0.1, 0.1, -1e-9])"), "'ambient'",
       "an array of 3 finite numbers, each in [0, 1000]"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    const std::string msg = error_of(c.text);
    INFO("message: " << msg);
    CHECK(msg.rfind("scenes/bad.json: ", 0) == 0);  // starts with the file
    CHECK_THAT(msg, Catch::Matchers::Contains("field " + c.field));
    CHECK_THAT(msg, Catch::Matchers::Contains(c.expected));
  }
}

TEST_CASE("JSON syntax errors give the file, line and column", "[scene][json]") {
  const std::string msg = error_of("{\n  \"image\": {\"width\": 64,\n  \"height\": }\n}\n");
  CHECK(msg.rfind("scenes/bad.json: ", 0) == 0);
  CHECK_THAT(msg, Catch::Matchers::Contains("invalid JSON at line 3"));
}

TEST_CASE("a missing scene file is named in the error", "[scene][json]") {
  try {
    load_scene("/nonexistent/dir/none.json");
    FAIL("no exception");
  } catch (const SceneError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Matchers::StartsWith("/nonexistent/dir/none.json: "));
  }
}

// Found by fuzzing (tests/fuzz): nlohmann reports a number beyond the double range as
// out_of_range, which escaped parse_scene before the fix.
TEST_CASE("a number beyond the double range is a SceneError, not another exception", "[scene][json]") {
  for (const std::string text : {std::string("1e1888888e]"), std::string("{\"image\": {\"width\": 1e400}}")}) {
    INFO(text);
    const std::string msg = error_of(text);
    CHECK(msg.rfind("scenes/bad.json: ", 0) == 0);
    CHECK_THAT(msg, Catch::Matchers::Contains("invalid JSON"));
  }
}
