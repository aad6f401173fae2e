// SPDX-License-Identifier: Apache-2.0
// `model` meshes (model/scene/model_file.hpp, format in scenes/README.md): tiny models
// written here in OBJ and ASCII PLY with known geometry, checked against closed forms:
// the fit, the rotation, angle-weighted generated normals, the file's own normals,
// triangulation, every error case; and the repository's model scenes.
#include "image.hpp"
#include "model_file.hpp"
#include "raster.hpp"
#include "raster_checks.hpp"
#include "scene.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

using namespace specular;
using Catch::Matchers::Contains;
using glm::dvec3;
namespace fs = std::filesystem;

namespace {

constexpr double kTol = 1e-9;

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("model_files_" + std::to_string(::getpid()) + "_" + tag);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

bool near(const dvec3& a, const dvec3& b, double tol = kTol) { return glm::length(a - b) <= tol; }

std::string str(const dvec3& v) {
  std::ostringstream os;
  os.precision(17);
  os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return os.str();
}

// Index of the output vertex at `p` (positions are unique in these tiny models).
size_t vertex_at(const Mesh& m, const dvec3& p) {
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (near(m.positions[i], p)) return i;
  FAIL("no vertex at " << str(p));
  return 0;
}

void box_of(const Mesh& m, dvec3& lo, dvec3& hi) {
  lo = hi = m.positions.at(0);
  for (const dvec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
}

// Rotations about the world axes, written out independently of model_rotation().
dvec3 rot_x(const dvec3& v, double deg) {
  const double a = deg * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
}
dvec3 rot_y(const dvec3& v, double deg) {
  const double a = deg * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}
dvec3 rot_z(const dvec3& v, double deg) {
  const double a = deg * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

// The corner tetrahedron O, X, Y, Z (unit axes), outward counter-clockwise faces, no normals.
const char* kTetraObj =
    "# corner tetrahedron\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\n"   // z = 0, normal -z
    "f 1 2 4\n"   // y = 0, normal -y
    "f 1 4 3\n"   // x = 0, normal -x
    "f 2 3 4\n";  // slanted, normal (1, 1, 1) / sqrt 3

// A unit cube of six quads (outward, counter-clockwise), no normals.
const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

// A quad in the plane z = 1 with the same tilted normal at every vertex: not the
// geometric normal, so a kept file normal is told apart from a generated one.
const char* kQuadPly =
    "ply\n"
    "format ascii 1.0\n"
    "comment a tilted-normal quad\n"
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "element face 1\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 1 0 0.6 0.8\n"
    "2 0 1 0 0.6 0.8\n"
    "2 1 1 0 0.6 0.8\n"
    "0 1 1 0 0.6 0.8\n"
    "4 0 1 2 3\n";

ModelFit identity_fit(const dvec3& center, double size) {
  ModelFit f;
  f.center = center;
  f.size = size;
  return f;
}

std::string load_error(const std::string& path, const ModelFit& fit = {}) {
  try {
    load_model_mesh(path, fit);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string scene_with_model(const std::string& model_fields) {
  return R"({
  "image": {"width": 32, "height": 32},
  "camera": {"type": "orthographic", "position": [0, 0, 10], "look_at": [0, 0, 0], "height": 3},
  "materials": [{"name": "m", "n": 20, "ks": 0.5}],
  "lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 1}],
  "meshes": [{"type": "model", "material": "m", )" +
         model_fields + "}]\n}\n";
}

std::string scene_error(const fs::path& scene_file, const std::string& text) {
  write(scene_file, text);
  try {
    load_scene(scene_file.string());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("model fit: largest box side becomes fit_size, box centre goes to fit_center", "[scene][model]") {
  const fs::path dir = temp_dir("fit");
  // Box [1, 5] x [2, 4] x [3, 4]: largest side 4 along x, centre (3, 3, 3.5).
  const fs::path obj = write(dir / "t.obj", "v 1 2 3\nv 5 2 3\nv 1 4 3\nv 1 2 4\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const dvec3 center{0.5, -1.25, 2.0};
  const Mesh m = load_model_mesh(obj.string(), identity_fit(center, 3.0));
  CHECK(m.kind == "model");
  CHECK(m.triangles.size() == 4);
  CHECK(m.positions.size() == 4);
  dvec3 lo, hi;
  box_of(m, lo, hi);
  const dvec3 ext = hi - lo;
  CHECK(std::abs(std::max({ext.x, ext.y, ext.z}) - 3.0) <= kTol);
  CHECK(near(0.5 * (lo + hi), center));
  // Every vertex: center + (3 / 4) (p - (3, 3, 3.5)).
  for (const dvec3 p : {dvec3(1, 2, 3), dvec3(5, 2, 3), dvec3(1, 4, 3), dvec3(1, 2, 4)})
    vertex_at(m, center + 0.75 * (p - dvec3(3, 3, 3.5)));
  fs::remove_all(dir);
}

TEST_CASE("model rotation: x, then y, then z about fit_center", "[scene][model]") {
  const fs::path dir = temp_dir("rot");
  const fs::path obj = write(dir / "t.obj", kTetraObj);
  const dvec3 center{1, 2, 3};
  ModelFit fit = identity_fit(center, 2.0);  // box [0, 1]^3: scale 2, centre (0.5, 0.5, 0.5)
  fit.rotate_deg = {30, -45, 100};
  const Mesh m = load_model_mesh(obj.string(), fit);
  REQUIRE(m.positions.size() == 4);
  for (const dvec3 p : {dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)}) {
    const dvec3 d = 2.0 * (p - dvec3(0.5));
    const dvec3 expect = center + rot_z(rot_y(rot_x(d, 30), -45), 100);
    INFO("vertex " << str(p) << " expected at " << str(expect));
    vertex_at(m, expect);
  }
  // The generated normal at O turns with the model: R (-1, -1, -1) / sqrt 3.
  const dvec3 o = center + rot_z(rot_y(rot_x(dvec3(-1), 30), -45), 100);
  const dvec3 n_expect = rot_z(rot_y(rot_x(dvec3(-1) / std::sqrt(3.0), 30), -45), 100);
  CHECK(near(m.normals[vertex_at(m, o)], n_expect));

  // Quarter turns are exact: (x, y, z) -> (-y, x, z) about z, bit for bit.
  fit.rotate_deg = {0, 0, 90};
  const Mesh q = load_model_mesh(obj.string(), fit);
  const glm::dmat3 r = model_rotation({0, 0, 90});
  CHECK(r * dvec3(1, 0, 0) == dvec3(0, 1, 0));
  CHECK(r * dvec3(0, 1, 0) == dvec3(-1, 0, 0));
  // X: d = 2 ((1, 0, 0) - (0.5, 0.5, 0.5)) = (1, -1, -1) -> (1, 1, -1).
  CHECK(q.positions[vertex_at(q, center + dvec3(1, 1, -1))] == center + dvec3(1, 1, -1));
  // Same rotation matrix entries as the closed form for a general angle triple.
  const glm::dmat3 g = model_rotation({10, 20, 30});
  for (const dvec3 e : {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)})
    CHECK(near(g * e, rot_z(rot_y(rot_x(e, 10), 20), 30), 1e-15));
  fs::remove_all(dir);
}

TEST_CASE("model normals: generated, angle-weighted, when the file has none", "[scene][model]") {
  const fs::path dir = temp_dir("gen");
  // Corner tetrahedron, fit that keeps its coordinates (size 1, centre (0.5, 0.5, 0.5)).
  const Mesh t = load_model_mesh(write(dir / "t.obj", kTetraObj).string(), identity_fit(dvec3(0.5), 1.0));
  REQUIRE(t.positions.size() == 4);
  // O: three faces, a right angle each, normals -x, -y, -z.
  CHECK(near(t.normals[vertex_at(t, {0, 0, 0})], dvec3(-1) / std::sqrt(3.0)));
  // X: the faces z = 0 and y = 0 meet it at 45 degrees, the slanted face at 60 degrees.
  const double q = std::numbers::pi / 4, s = std::numbers::pi / 3;
  const dvec3 nx = glm::normalize(q * dvec3(0, 0, -1) + q * dvec3(0, -1, 0) + s * dvec3(1) / std::sqrt(3.0));
  CHECK(near(t.normals[vertex_at(t, {1, 0, 0})], nx));
  // Y and Z by symmetry (permuted coordinates).
  CHECK(near(t.normals[vertex_at(t, {0, 1, 0})], dvec3(nx.z, nx.x, nx.y)));
  CHECK(near(t.normals[vertex_at(t, {0, 0, 1})], dvec3(nx.y, nx.z, nx.x)));

  // Cube of quads: whichever diagonal a face is cut along, each corner's three faces weigh
  // 90 degrees each, so every corner normal is the diagonal (an area weighting would
  // count a face twice where both its triangles touch the corner).
  const Mesh c = load_model_mesh(write(dir / "cube.obj", kCubeObj).string(), identity_fit(dvec3(0.5), 1.0));
  CHECK(c.triangles.size() == 12);
  REQUIRE(c.positions.size() == 8);
  for (size_t i = 0; i < 8; ++i) {
    const dvec3 expect = glm::normalize(c.positions[i] - dvec3(0.5));
    INFO("corner " << str(c.positions[i]));
    CHECK(near(c.normals[i], expect));
  }
  fs::remove_all(dir);
}

TEST_CASE("model normals: the file normals are kept and rotated, a quad is triangulated", "[scene][model]") {
  const fs::path dir = temp_dir("own");
  const fs::path ply = write(dir / "quad.ply", kQuadPly);
  ModelFit fit = identity_fit({0, 0, 0}, 4.0);  // box [0, 2] x [0, 1] x {1}: scale 2
  const Mesh m = load_model_mesh(ply.string(), fit);
  // One quad face: two triangles over the four vertices, covering area 4 x 2.
  REQUIRE(m.triangles.size() == 2);
  CHECK(m.positions.size() == 4);
  double area = 0;
  for (const auto& tr : m.triangles) {
    const dvec3 n = glm::cross(m.positions[tr[1]] - m.positions[tr[0]], m.positions[tr[2]] - m.positions[tr[0]]);
    area += 0.5 * glm::length(n);
    CHECK(n.z > 0);  // the face's winding is kept (counter-clockwise seen from +z)
  }
  CHECK(std::abs(area - 8.0) <= kTol);
  for (size_t i = 0; i < 4; ++i) CHECK(near(m.normals[i], dvec3(0, 0.6, 0.8), 1e-7));  // floats in the file

  fit.rotate_deg = {90, 0, 0};  // (x, y, z) -> (x, -z, y)
  const Mesh r = load_model_mesh(ply.string(), fit);
  REQUIRE(r.positions.size() == 4);
  for (size_t i = 0; i < 4; ++i) {
    CHECK(near(r.normals[i], dvec3(0, -0.8, 0.6), 1e-7));
    CHECK(std::abs(glm::length(r.normals[i]) - 1.0) <= 1e-15);
  }
  vertex_at(r, {2, 0, -1});  // (2, 0, 1) - (1, 0.5, 1) = (1, -0.5, 0), x 2, rotated: (2, 0, -1)

  // The same quad as an OBJ without normals: triangulated too, normals generated (+z).
  const Mesh o = load_model_mesh(write(dir / "quad.obj", "v 0 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\nf 1 2 3 4\n").string(),
                                 identity_fit({0, 0, 0}, 4.0));
  CHECK(o.triangles.size() == 2);
  for (const dvec3& n : o.normals) CHECK(near(n, dvec3(0, 0, 1)));
  fs::remove_all(dir);
}

TEST_CASE("model: merged meshes of a file, dropped points, lines and zero-area triangles", "[scene][model]") {
  const fs::path dir = temp_dir("mixed");
  // Two OBJ groups (two assimp meshes), a stray far point, a line and a zero-area
  // triangle reaching x = 10: none of them appears or moves the fit.
  const fs::path obj = write(dir / "two.obj",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nv 3 0 0\nv 4 0 0\nv 3 1 0\nv 10 0 0\n"
                             "g a\nf 1 2 3\np 4\nl 1 4\nf 1 2 8\ng b\nf 5 6 7\n");
  const Mesh m = load_model_mesh(obj.string(), identity_fit({0, 0, 0}, 4.0));
  CHECK(m.triangles.size() == 2);
  CHECK(m.positions.size() == 6);
  dvec3 lo, hi;
  box_of(m, lo, hi);
  CHECK(near(lo, {-2, -0.5, 0}));
  CHECK(near(hi, {2, 0.5, 0}));
  fs::remove_all(dir);
}

TEST_CASE("model errors: missing, unreadable, garbage, no triangles, bad fit", "[scene][model]") {
  const fs::path dir = temp_dir("err");
  const std::string missing = (dir / "none.obj").string();
  std::string e = load_error(missing);
  CHECK_THAT(e, Contains(missing));
  CHECK_THAT(e, Contains("no such file"));

  e = load_error(dir.string());
  CHECK_THAT(e, Contains(dir.string()));
  CHECK_THAT(e, Contains("not a regular file"));

  const fs::path garbage = write(dir / "garbage.ply", "this is not a PLY file\n\x01\x02\x03 at all\n");
  e = load_error(garbage.string());
  CHECK_THAT(e, Contains(garbage.string()));
  CHECK_THAT(e, Contains("assimp cannot read the model file: "));
  const fs::path unknown = write(dir / "garbage.xyz123", std::string("\x7f\x13\x00\xff binary junk", 17));
  e = load_error(unknown.string());
  CHECK_THAT(e, Contains(unknown.string()));
  CHECK_THAT(e, Contains("assimp cannot read the model file: "));

  const fs::path lines = write(dir / "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
  e = load_error(lines.string());
  CHECK_THAT(e, Contains(lines.string()));
  CHECK_THAT(e, Contains("no triangles"));

  const fs::path flat = write(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  e = load_error(flat.string());
  CHECK_THAT(e, Contains("no triangles of non-zero area"));

  const fs::path ok = write(dir / "t.obj", kTetraObj);
  e = load_error(ok.string(), identity_fit({0, 0, 0}, 0.0));
  CHECK_THAT(e, Contains(ok.string()));
  CHECK_THAT(e, Contains("fit size must be a finite number > 0"));
  e = load_error(ok.string(), identity_fit({0, 0, 0}, std::nan("")));
  CHECK_THAT(e, Contains("fit size"));
  e = load_error(ok.string(), identity_fit({0, INFINITY, 0}, 1.0));
  CHECK_THAT(e, Contains("fit centre"));
  fs::remove_all(dir);
}

TEST_CASE("model meshes in scene files: relative paths, and errors name the scene file and field", "[scene][model]") {
  const fs::path dir = temp_dir("scene");
  fs::create_directories(dir / "models");
  write(dir / "models" / "t.obj", kTetraObj);
  const fs::path sf = dir / "s.json";

  // Relative to the scene file's directory, not to the working directory.
  write(sf, scene_with_model(R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": 2, "rotate_deg": [0, 90, 0])"));
  const Scene s = load_scene(sf.string());
  REQUIRE(s.meshes.size() == 1);
  CHECK(s.meshes[0].kind == "model");
  CHECK(s.meshes[0].triangles.size() == 4);
  const Raster r = rasterize(s);
  CHECK(r.spans.size() > 0);
  // rotate_deg defaults to no rotation; an absolute path is used as it is.
  write(sf, scene_with_model(R"("path": ")" + (dir / "models" / "t.obj").string() +
                             R"(", "fit_center": [0, 0, 0], "fit_size": 2)"));
  CHECK(load_scene(sf.string()).meshes[0].triangles.size() == 4);

  struct Bad {
    std::string fields, field, reason;
  };
  const Bad bad[] = {
      {R"("path": "models/none.obj", "fit_center": [0, 0, 0], "fit_size": 2)", "meshes[0].path",
       (dir / "models" / "none.obj").string() + ": cannot read the model file: no such file"},
      {R"("path": "", "fit_center": [0, 0, 0], "fit_size": 2)", "meshes[0].path", "a non-empty path"},
      {R"("path": 3, "fit_center": [0, 0, 0], "fit_size": 2)", "meshes[0].path", "a string"},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": 0)", "meshes[0].fit_size", "(0, "},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": -1)", "meshes[0].fit_size", "(0, "},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": "big")", "meshes[0].fit_size", "(0, "},
      {R"("path": "models/t.obj", "fit_center": [0, 0], "fit_size": 1)", "meshes[0].fit_center", "3 finite numbers"},
      {R"("path": "models/t.obj", "fit_size": 1)", "meshes[0].fit_center", "missing"},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0])", "meshes[0].fit_size", "missing"},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": 1, "rotate_deg": [0, "x", 0])",
       "meshes[0].rotate_deg", "3 finite numbers"},
      {R"("path": "models/t.obj", "fit_center": [0, 0, 0], "fit_size": 1, "scale": 2)", "meshes[0].scale",
       "unknown field"},
  };
  for (const Bad& b : bad) {
    const std::string e = scene_error(sf, scene_with_model(b.fields));
    INFO(b.fields);
    CHECK(e.rfind(sf.string() + ": field '" + b.field + "'", 0) == 0);
    CHECK_THAT(e, Contains(b.reason));
  }
  write(dir / "models" / "lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  std::string e = scene_error(sf, scene_with_model(R"("path": "models/lines.obj", "fit_center": [0, 0, 0], "fit_size": 1)"));
  CHECK_THAT(e, Contains(sf.string() + ": field 'meshes[0].path'"));
  CHECK_THAT(e, Contains("no triangles"));

  // SceneOptions::model_file_allowed sees the resolved path and can refuse it.
  std::string seen;
  SceneOptions opt;
  opt.model_file_allowed = [&](const std::string& p) {
    seen = p;
    return false;
  };
  write(sf, scene_with_model(R"("path": "models/../models/t.obj", "fit_center": [0, 0, 0], "fit_size": 2)"));
  try {
    load_scene(sf.string(), opt);
    FAIL("refused path loaded");
  } catch (const SceneError& err) {
    CHECK_THAT(err.what(), Contains("meshes[0].path"));
    CHECK_THAT(err.what(), Contains("outside what it allows"));
  }
  CHECK(seen == (dir / "models" / "t.obj").string());
  fs::remove_all(dir);
}

TEST_CASE("render: a scene with a bad model file exits with 2 and writes nothing", "[scene][model][cli]") {
  const fs::path dir = temp_dir("cli");
  const fs::path sf = dir / "bad.json";
  write(dir / "garbage.ply", "not a ply\n");
  write(sf, scene_with_model(R"("path": "garbage.ply", "fit_center": [0, 0, 0], "fit_size": 2)"));
  const fs::path out = dir / "img";
  const std::string cmd = std::string(SCENE_RENDER_TOOL) + " --scene " + sf.string() + " --out-dir " + out.string() +
                          " > " + (dir / "stdout.txt").string() + " 2> " + (dir / "stderr.txt").string();
  const int status = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 2);
  std::ifstream in(dir / "stderr.txt");
  std::ostringstream err;
  err << in.rdbuf();
  CHECK_THAT(err.str(), Contains(sf.string()));
  CHECK_THAT(err.str(), Contains("meshes[0].path"));
  CHECK_THAT(err.str(), Contains("assimp cannot read the model file"));
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

// The repository's model scenes read Debian files that scripts/install-deps.sh installs
// (glmark2-data, assimp-testmodels); they are required, not skipped.
namespace {

// What tests/scene/test_repo_scenes.cpp checks of every listed scene (raster_checks.hpp), for the model
// scenes: every triangle rasterized, spans disjoint and inside the image, C unsaturated.
void check_raster(const Scene& s) {
  const Raster r = rasterize(s);
  const device::Format f;
  size_t saturated = 0;
  test::check_spans(s, r, [&](const Span& sp) {
    bool sat = false;
    host::span_registers(sp.setup_in, f, &sat);
    saturated += sat;
  });
  CHECK(saturated == 0);
}

}  // namespace

TEST_CASE("bunny.json: the glmark2 Stanford bunny, every triangle of the file", "[scene][model][repo]") {
  const char* file = "/usr/share/glmark2/models/bunny.obj";
  INFO(file << " comes from the Debian package glmark2-data (scripts/install-deps.sh)");
  REQUIRE(fs::exists(file));
  const Scene s = load_scene("scenes/bunny.json");
  REQUIRE(s.meshes.size() == 1);
  const Mesh& m = s.meshes[0];
  CHECK(m.kind == "model");
  // Counted in the file: 69,666 "f" lines, all triangles, over 34,835 "v" lines, no "vn".
  CHECK(m.triangles.size() == 69'666);
  CHECK(m.positions.size() == 34'835);
  // Generated normals face outwards: most point away from the centroid (a closed scan
  // with concave parts, so not all).
  dvec3 c(0);
  for (const dvec3& p : m.positions) c += p;
  c /= static_cast<double>(m.positions.size());
  size_t out = 0;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    REQUIRE(std::abs(glm::length(m.normals[i]) - 1.0) < 1e-12);
    out += glm::dot(m.normals[i], m.positions[i] - c) > 0;
  }
  CHECK(out > m.positions.size() * 8 / 10);  // measured 90 %
  check_raster(s);
}

TEST_CASE("duck.json: the COLLADA duck of assimp's test models", "[scene][model][repo]") {
  const char* file = "/usr/share/assimp/models/Collada/duck.dae";
  INFO(file << " comes from the Debian package assimp-testmodels (scripts/install-deps.sh)");
  REQUIRE(fs::exists(file));
  const Scene s = load_scene("scenes/duck.json");
  REQUIRE(s.meshes.size() == 1);
  CHECK(s.meshes[0].kind == "model");
  // Counted in the file: one <polylist> of 2,144 polygons (<vcount>: 84 triangles, 2,052
  // quads, 8 pentagons) = 84 + 2 x 2,052 + 3 x 8 = 4,212 triangles.
  CHECK(s.meshes[0].triangles.size() == 4'212);
  check_raster(s);
}
