// SPDX-License-Identifier: Apache-2.0
// Scene loading (nlohmann::json) and mesh generation. See scene.hpp and scenes/README.md.
#include "scene.hpp"

#include "coefficients.hpp"
#include "model_file.hpp"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

namespace specular {

using json = nlohmann::json;
using glm::dvec3;

// ---------------------------------------------------------------- geometry helpers

dvec3 Light::to_light(const dvec3& p) const {
  if (type == LightType::directional) return direction;
  return glm::normalize(position - p);
}

dvec3 Camera::forward() const { return glm::normalize(look_at - position); }
dvec3 Camera::right() const { return glm::normalize(glm::cross(forward(), up)); }
dvec3 Camera::true_up() const { return glm::cross(right(), forward()); }

dvec3 Camera::to_viewer(const dvec3& p) const {
  // Orthographic: the viewer is at infinity behind the image plane.
  if (type == CameraType::orthographic) return -forward();
  return glm::normalize(position - p);
}

const std::vector<BrdfChoice>& brdf_choices() {
  // Every shape of brdf.hpp that is a function of the angle between N and H and stands in for
  // cos^n in a Blinn-Phong pipeline, plain and with its own normalization; f16 is Lyon's shape
  // (m = 16) with its fitted normalization. Phong (the angle between V and R) and the cos^k(a x)
  // family of the device itself are not materials.
  static const std::vector<BrdfChoice> choices = {
      {"blinn_phong", Model::blinn, false},   {"blinn_phong_normalized", Model::blinn, true},
      {"schlick", Model::schlick, false},     {"schlick_normalized", Model::schlick, true},
      {"schlick_mod", Model::schlick_mod, false}, {"schlick_mod_normalized", Model::schlick_mod, true},
      {"lyon", Model::lyon, false},           {"lyon_normalized", Model::lyon, true},
      {"f16", Model::f16, true},
  };
  return choices;
}

size_t Scene::triangle_count() const {
  size_t n = 0;
  for (const auto& m : meshes) n += m.triangles.size();
  return n;
}

namespace {

// Any unit vector orthogonal to unit a.
dvec3 any_perpendicular(const dvec3& a) {
  dvec3 t = std::abs(a.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
  return glm::normalize(glm::cross(a, t));
}

}  // namespace

Mesh make_sphere(const dvec3& center, double radius, int t, const dvec3& axis_in) {
  const dvec3 axis = glm::normalize(axis_in);
  const dvec3 e1 = any_perpendicular(axis);
  const dvec3 e2 = glm::cross(axis, e1);
  const int segs = 2 * t, rings = t;
  Mesh m;
  m.kind = "sphere";
  auto add = [&](const dvec3& nrm) {
    m.positions.push_back(center + radius * nrm);
    m.normals.push_back(nrm);
  };
  add(axis);  // north pole: index 0
  for (int r = 1; r < rings; ++r) {
    const double th = std::numbers::pi * r / rings;
    for (int s = 0; s < segs; ++s) {
      const double ph = 2 * std::numbers::pi * s / segs;
      add(glm::normalize(std::cos(th) * axis + std::sin(th) * (std::cos(ph) * e1 + std::sin(ph) * e2)));
    }
  }
  add(-axis);  // south pole: last index
  const int south = static_cast<int>(m.positions.size()) - 1;
  auto ring_vertex = [&](int r, int s) { return 1 + (r - 1) * segs + (s % segs); };  // r in 1..rings-1
  for (int s = 0; s < segs; ++s) {
    m.triangles.push_back({0, ring_vertex(1, s), ring_vertex(1, s + 1)});
    m.triangles.push_back({south, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s)});
  }
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segs; ++s) {
      const int a = ring_vertex(r, s), b = ring_vertex(r, s + 1);
      const int c = ring_vertex(r + 1, s), d = ring_vertex(r + 1, s + 1);
      m.triangles.push_back({a, c, d});
      m.triangles.push_back({a, d, b});
    }
  }
  return m;
}

Mesh make_torus(const dvec3& center, double R, double r, int t, const dvec3& axis_in) {
  const dvec3 axis = glm::normalize(axis_in);
  const dvec3 e1 = any_perpendicular(axis);
  const dvec3 e2 = glm::cross(axis, e1);
  const int segs = 2 * t, sides = t;
  Mesh m;
  m.kind = "torus";
  for (int s = 0; s < segs; ++s) {
    const double u = 2 * std::numbers::pi * s / segs;
    const dvec3 radial = std::cos(u) * e1 + std::sin(u) * e2;
    for (int k = 0; k < sides; ++k) {
      const double v = 2 * std::numbers::pi * k / sides;
      const dvec3 nrm = glm::normalize(std::cos(v) * radial + std::sin(v) * axis);
      m.positions.push_back(center + R * radial + r * nrm);
      m.normals.push_back(nrm);
    }
  }
  auto idx = [&](int s, int k) { return (s % segs) * sides + (k % sides); };
  for (int s = 0; s < segs; ++s) {
    for (int k = 0; k < sides; ++k) {
      const int a = idx(s, k), b = idx(s + 1, k), c = idx(s, k + 1), d = idx(s + 1, k + 1);
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  }
  return m;
}

Mesh make_plane(const dvec3& center, const dvec3& normal_in, const dvec3& tangent_in, double su,
                double sv, int t) {
  const dvec3 nrm = glm::normalize(normal_in);
  // Gram-Schmidt: the tangent only needs to be non-parallel to the normal.
  const dvec3 eu = glm::normalize(tangent_in - glm::dot(tangent_in, nrm) * nrm);
  const dvec3 ev = glm::cross(nrm, eu);
  Mesh m;
  m.kind = "plane";
  for (int j = 0; j <= t; ++j) {
    for (int i = 0; i <= t; ++i) {
      const double a = (static_cast<double>(i) / t - 0.5) * su;
      const double b = (static_cast<double>(j) / t - 0.5) * sv;
      m.positions.push_back(center + a * eu + b * ev);
      m.normals.push_back(nrm);
    }
  }
  auto idx = [&](int i, int j) { return j * (t + 1) + i; };
  for (int j = 0; j < t; ++j) {
    for (int i = 0; i < t; ++i) {
      m.triangles.push_back({idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)});
      m.triangles.push_back({idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)});
    }
  }
  return m;
}

// ---------------------------------------------------------------- JSON loading

namespace {

// Reads fields of one JSON object and reports errors as "<file>: field '<path>': expected ...".
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& expected, const json* got) const {
    std::ostringstream os;
    os << file_ << ": field '" << field << "': expected " << expected;
    if (got) {
      std::string g = got->dump();
      if (g.size() > 60) g = g.substr(0, 57) + "...";
      os << ", got " << g;
    } else {
      os << ", but it is missing";
    }
    throw SceneError(os.str());
  }

  const json& require(const json& obj, const std::string& key, const std::string& field,
                      const std::string& expected) const {
    auto it = obj.find(key);
    if (it == obj.end()) fail(field, expected, nullptr);
    return *it;
  }

  const json& object(const json& obj, const std::string& key, const std::string& field) const {
    const json& v = require(obj, key, field, "an object");
    if (!v.is_object()) fail(field, "an object", &v);
    return v;
  }

  const json& array(const json& obj, const std::string& key, const std::string& field, size_t min_size) const {
    const std::string what = "an array with at least " + std::to_string(min_size) + " element(s)";
    const json& v = require(obj, key, field, what);
    if (!v.is_array() || v.size() < min_size) fail(field, what, &v);
    return v;
  }

  static std::string range_text(double lo, double hi, bool lo_open) {
    std::ostringstream os;
    os << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
    return os.str();
  }

  double number_value(const json& v, const std::string& field, double lo, double hi, bool lo_open) const {
    const std::string what = "a number in " + range_text(lo, hi, lo_open);
    if (!v.is_number()) fail(field, what, &v);
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi || (lo_open && x == lo)) fail(field, what, &v);
    return x;
  }

  double number(const json& obj, const std::string& key, const std::string& field, double lo, double hi,
                bool lo_open = false) const {
    const json& v = require(obj, key, field, "a number in " + range_text(lo, hi, lo_open));
    return number_value(v, field, lo, hi, lo_open);
  }

  double number_or(const json& obj, const std::string& key, const std::string& field, double lo, double hi,
                   double dflt, bool lo_open = false) const {
    if (!obj.contains(key)) return dflt;
    return number(obj, key, field, lo, hi, lo_open);
  }

  int integer(const json& obj, const std::string& key, const std::string& field, int lo, int hi) const {
    const std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    const json& v = require(obj, key, field, what);
    if (!v.is_number_integer()) fail(field, what, &v);
    const long long x = v.get<long long>();
    if (x < lo || x > hi) fail(field, what, &v);
    return static_cast<int>(x);
  }

  std::string string_value(const json& obj, const std::string& key, const std::string& field,
                           const std::vector<std::string>& allowed) const {
    std::string what = "a string";
    if (!allowed.empty()) {
      what = "one of";
      for (size_t i = 0; i < allowed.size(); ++i) what += (i ? ", \"" : " \"") + allowed[i] + "\"";
    }
    const json& v = require(obj, key, field, what);
    if (!v.is_string()) fail(field, what, &v);
    std::string s = v.get<std::string>();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end()) fail(field, what, &v);
    return s;
  }

  dvec3 vec3_value(const json& v, const std::string& field, bool nonzero) const {
    const std::string what = nonzero ? "an array of 3 finite numbers, not all zero" : "an array of 3 finite numbers";
    if (!v.is_array() || v.size() != 3) fail(field, what, &v);
    dvec3 r;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) fail(field, what, &v);
      r[i] = v[i].get<double>();
    }
    if (nonzero && glm::length(r) == 0.0) fail(field, what, &v);
    return r;
  }

  dvec3 vec3(const json& obj, const std::string& key, const std::string& field, bool nonzero = false) const {
    const json& v = require(obj, key, field, "an array of 3 finite numbers");
    return vec3_value(v, field, nonzero);
  }

  dvec3 vec3_or(const json& obj, const std::string& key, const std::string& field, const dvec3& dflt,
                bool nonzero = false) const {
    if (!obj.contains(key)) return dflt;
    return vec3(obj, key, field, nonzero);
  }

  // A colour: exactly 3 finite numbers, each in [0, hi].
  dvec3 colour_or(const json& obj, const std::string& key, const std::string& field, const dvec3& dflt,
                  double hi) const {
    if (!obj.contains(key)) return dflt;
    const json& v = obj[key];
    const std::string what = "an array of 3 finite numbers, each in " + range_text(0.0, hi, false);
    if (!v.is_array() || v.size() != 3) fail(field, what, &v);
    dvec3 r;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number()) fail(field, what, &v);
      r[i] = v[i].get<double>();
      if (!std::isfinite(r[i]) || r[i] < 0.0 || r[i] > hi) fail(field, what, &v);
    }
    return r;
  }

  // Rejects keys that are not in `known` (catches typos such as "radus").
  void only_keys(const json& obj, const std::string& field, const std::vector<std::string>& known) const {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (std::find(known.begin(), known.end(), it.key()) == known.end()) {
        std::string what = "no field '" + it.key() + "' (allowed:";
        for (const auto& k : known) what += " " + k;
        what += ")";
        std::ostringstream os;
        os << file_ << ": field '" << (field.empty() ? "" : field + ".") << it.key() << "': unknown field, expected "
           << what;
        throw SceneError(os.str());
      }
    }
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

Camera parse_camera(const Reader& rd, const json& root) {
  const json& c = rd.object(root, "camera", "camera");
  rd.only_keys(c, "camera", {"type", "position", "look_at", "up", "fov_y_deg", "height", "near"});
  Camera cam;
  const std::string type = rd.string_value(c, "type", "camera.type", {"orthographic", "perspective"});
  cam.type = type == "orthographic" ? CameraType::orthographic : CameraType::perspective;
  cam.position = rd.vec3(c, "position", "camera.position");
  cam.look_at = rd.vec3(c, "look_at", "camera.look_at");
  cam.up = rd.vec3_or(c, "up", "camera.up", {0, 1, 0}, true);
  if (glm::length(cam.look_at - cam.position) == 0.0)
    rd.fail("camera.look_at", "a point different from camera.position", &c["look_at"]);
  const dvec3 f = glm::normalize(cam.look_at - cam.position);
  if (glm::length(glm::cross(f, glm::normalize(cam.up))) < 1e-9)
    rd.fail("camera.up", "a direction not parallel to the viewing direction", &c["up"]);
  if (cam.type == CameraType::perspective) {
    cam.fov_y_deg = rd.number(c, "fov_y_deg", "camera.fov_y_deg", 1.0, 170.0);
    cam.near = rd.number_or(c, "near", "camera.near", 0.0, 1e6, 1e-3, true);
  } else {
    cam.height = rd.number(c, "height", "camera.height", 0.0, 1e9, true);
  }
  return cam;
}

std::vector<Material> parse_materials(const Reader& rd, const json& root) {
  const json& arr = rd.array(root, "materials", "materials", 1);
  std::vector<Material> out;
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string f = "materials[" + std::to_string(i) + "]";
    if (!arr[i].is_object()) rd.fail(f, "an object", &arr[i]);
    rd.only_keys(arr[i], f, {"name", "n", "ks", "norm", "diffuse", "specular", "emission", "brdf"});
    Material m;
    m.name = rd.string_value(arr[i], "name", f + ".name", {});
    for (const auto& prev : out)
      if (prev.name == m.name) rd.fail(f + ".name", "a name not used by another material", &arr[i]["name"]);
    m.n = rd.number(arr[i], "n", f + ".n", 1.0, kMaxN);
    m.ks = rd.number(arr[i], "ks", f + ".ks", 0.0, 1.0);
    m.norm = rd.number_or(arr[i], "norm", f + ".norm", 0.0, 1e3, 1.0, true);
    m.diffuse = rd.colour_or(arr[i], "diffuse", f + ".diffuse", dvec3(0.0), kMaxReflectance);
    if (arr[i].contains("specular"))
      m.specular = rd.colour_or(arr[i], "specular", f + ".specular", dvec3(0.0), kMaxReflectance);
    m.emission = rd.colour_or(arr[i], "emission", f + ".emission", dvec3(0.0), kMaxRadiance);
    if (arr[i].contains("brdf")) {
      std::vector<std::string> names;
      for (const auto& c : brdf_choices()) names.push_back(c.name);
      const std::string b = rd.string_value(arr[i], "brdf", f + ".brdf", names);
      for (const auto& c : brdf_choices())
        if (c.name == b) m.brdf = c;
    }
    out.push_back(m);
  }
  return out;
}

std::vector<Light> parse_lights(const Reader& rd, const json& root) {
  const json& arr = rd.array(root, "lights", "lights", 1);
  std::vector<Light> out;
  for (size_t i = 0; i < arr.size(); ++i) {
    const std::string f = "lights[" + std::to_string(i) + "]";
    if (!arr[i].is_object()) rd.fail(f, "an object", &arr[i]);
    Light l;
    const std::string type = rd.string_value(arr[i], "type", f + ".type", {"directional", "point"});
    l.intensity = rd.number(arr[i], "intensity", f + ".intensity", 0.0, 1e3, true);
    if (arr[i].contains("color")) l.color = rd.colour_or(arr[i], "color", f + ".color", dvec3(0.0), kMaxRadiance);
    if (type == "directional") {
      rd.only_keys(arr[i], f, {"type", "direction", "intensity", "color"});
      l.type = LightType::directional;
      l.direction = glm::normalize(rd.vec3(arr[i], "direction", f + ".direction", true));
    } else {
      rd.only_keys(arr[i], f, {"type", "position", "intensity", "color"});
      l.type = LightType::point;
      l.position = rd.vec3(arr[i], "position", f + ".position");
    }
    out.push_back(l);
  }
  return out;
}

// A `model` mesh: the file is resolved against the scene file's directory and read by
// load_model_mesh (model_file.hpp); its errors are reported on the `path` field.
Mesh parse_model(const Reader& rd, const json& m, const std::string& f, const SceneOptions& opt) {
  rd.only_keys(m, f, {"type", "material", "path", "fit_center", "fit_size", "rotate_deg"});
  const std::string rel = rd.string_value(m, "path", f + ".path", {});
  if (rel.empty()) rd.fail(f + ".path", "a non-empty path of a model file", &m["path"]);
  if (rel.find('\0') != std::string::npos) rd.fail(f + ".path", "a path without NUL characters", &m["path"]);
  ModelFit fit;
  fit.center = rd.vec3(m, "fit_center", f + ".fit_center");
  fit.size = rd.number(m, "fit_size", f + ".fit_size", 0.0, 1e9, true);
  fit.rotate_deg = rd.vec3_or(m, "rotate_deg", f + ".rotate_deg", {0, 0, 0});
  namespace fs = std::filesystem;
  const fs::path p(rel);
  const std::string resolved =
      (p.is_absolute() ? p : fs::path(rd.file()).parent_path() / p).lexically_normal().string();
  if (opt.model_file_allowed && !opt.model_file_allowed(resolved))
    rd.fail(f + ".path", "a model file this loader may read (" + resolved + " is outside what it allows)", &m["path"]);
  try {
    return load_model_mesh(resolved, fit);
  } catch (const SceneError& e) {
    throw SceneError(rd.file() + ": field '" + f + ".path': expected a model file with triangles, but " + e.what());
  }
}

Mesh parse_mesh(const Reader& rd, const json& m, const std::string& f, const std::map<std::string, int>& mats,
                const SceneOptions& opt) {
  if (!m.is_object()) rd.fail(f, "an object", &m);
  const std::string type =
      rd.string_value(m, "type", f + ".type", {"triangles", "sphere", "torus", "plane", "model"});
  std::string mat_list;
  for (const auto& [k, v] : mats) mat_list += (mat_list.empty() ? "\"" : ", \"") + k + "\"";
  const std::string mname = rd.string_value(m, "material", f + ".material", {});
  auto mit = mats.find(mname);
  if (mit == mats.end()) rd.fail(f + ".material", "the name of a material (" + mat_list + ")", &m["material"]);

  Mesh mesh;
  if (type == "model") {
    mesh = parse_model(rd, m, f, opt);
  } else if (type == "sphere") {
    rd.only_keys(m, f, {"type", "material", "center", "radius", "tessellation", "axis"});
    mesh = make_sphere(rd.vec3(m, "center", f + ".center"), rd.number(m, "radius", f + ".radius", 0.0, 1e6, true),
                       rd.integer(m, "tessellation", f + ".tessellation", 3, kMaxTessellation),
                       rd.vec3_or(m, "axis", f + ".axis", {0, 1, 0}, true));
  } else if (type == "torus") {
    rd.only_keys(m, f, {"type", "material", "center", "major_radius", "minor_radius", "tessellation", "axis"});
    const double R = rd.number(m, "major_radius", f + ".major_radius", 0.0, 1e6, true);
    const double r = rd.number(m, "minor_radius", f + ".minor_radius", 0.0, 1e6, true);
    if (r >= R) rd.fail(f + ".minor_radius", "a number smaller than major_radius (" + std::to_string(R) + ")", &m["minor_radius"]);
    mesh = make_torus(rd.vec3(m, "center", f + ".center"), R, r,
                      rd.integer(m, "tessellation", f + ".tessellation", 3, kMaxTessellation),
                      rd.vec3_or(m, "axis", f + ".axis", {0, 1, 0}, true));
  } else if (type == "plane") {
    rd.only_keys(m, f, {"type", "material", "center", "normal", "tangent", "size", "tessellation"});
    const dvec3 nrm = glm::normalize(rd.vec3(m, "normal", f + ".normal", true));
    const dvec3 tan = rd.vec3_or(m, "tangent", f + ".tangent", any_perpendicular(nrm), true);
    if (glm::length(glm::cross(nrm, glm::normalize(tan))) < 1e-9)
      rd.fail(f + ".tangent", "a direction not parallel to the normal", &m["tangent"]);
    const json& size = rd.require(m, "size", f + ".size", "an array of 2 positive numbers");
    if (!size.is_array() || size.size() != 2) rd.fail(f + ".size", "an array of 2 positive numbers", &size);
    const double su = rd.number_value(size[0], f + ".size[0]", 0.0, 1e9, true);
    const double sv = rd.number_value(size[1], f + ".size[1]", 0.0, 1e9, true);
    mesh = make_plane(rd.vec3(m, "center", f + ".center"), nrm, tan, su, sv,
                      rd.integer(m, "tessellation", f + ".tessellation", 1, kMaxTessellation));
  } else {
    rd.only_keys(m, f, {"type", "material", "vertices", "normals", "triangles"});
    mesh.kind = "triangles";
    const json& vs = rd.array(m, "vertices", f + ".vertices", 3);
    const json& ns = rd.array(m, "normals", f + ".normals", 1);
    if (ns.size() != vs.size())
      rd.fail(f + ".normals", "one normal per vertex (" + std::to_string(vs.size()) + " normals)", &ns);
    for (size_t i = 0; i < vs.size(); ++i) {
      mesh.positions.push_back(rd.vec3_value(vs[i], f + ".vertices[" + std::to_string(i) + "]", false));
      mesh.normals.push_back(glm::normalize(rd.vec3_value(ns[i], f + ".normals[" + std::to_string(i) + "]", true)));
    }
    const json& ts = rd.array(m, "triangles", f + ".triangles", 1);
    const int nv = static_cast<int>(vs.size());
    for (size_t i = 0; i < ts.size(); ++i) {
      const std::string tf = f + ".triangles[" + std::to_string(i) + "]";
      const std::string what = "an array of 3 vertex indices in [0, " + std::to_string(nv - 1) + "]";
      const json& t = ts[i];
      if (!t.is_array() || t.size() != 3) rd.fail(tf, what, &t);
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        if (!t[k].is_number_integer() || t[k].get<long long>() < 0 || t[k].get<long long>() >= nv) rd.fail(tf, what, &t);
        tri[k] = static_cast<int>(t[k].get<long long>());
      }
      mesh.triangles.push_back(tri);
    }
  }
  mesh.material = mit->second;
  return mesh;
}

// 1-based line and column of a byte offset, for JSON syntax errors.
std::string line_col(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& path) { return parse_scene(text, path, SceneOptions{}); }

Scene parse_scene(const std::string& text, const std::string& path, const SceneOptions& options) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.byte is 1-based: the position of the offending character.
    throw SceneError(path + ": invalid JSON at " + line_col(text, e.byte ? e.byte - 1 : 0) +
                     ": expected a valid JSON document (" + e.what() + ")");
  } catch (const json::exception& e) {
    // Found by fuzzing (tests/fuzz/corpus/scene/crash_number_overflow.json): a number
    // beyond the double range ("1e1888888") is json::out_of_range, not parse_error, and
    // escaped as an uncaught exception.
    throw SceneError(path + ": invalid JSON: expected a valid JSON document with finite numbers (" +
                     e.what() + ")");
  }
  Reader rd(path);
  if (!root.is_object()) rd.fail("(top level)", "an object", &root);
  rd.only_keys(root, "", {"name", "description", "image", "camera", "materials", "lights", "meshes", "ambient"});

  Scene s;
  s.path = path;
  {
    const size_t slash = path.find_last_of("/\\");
    std::string stem = slash == std::string::npos ? path : path.substr(slash + 1);
    const size_t dot = stem.find_last_of('.');
    s.name = dot == std::string::npos ? stem : stem.substr(0, dot);
  }
  if (root.contains("name")) s.name = rd.string_value(root, "name", "name", {});
  if (root.contains("description")) rd.string_value(root, "description", "description", {});

  const json& img = rd.object(root, "image", "image");
  rd.only_keys(img, "image", {"width", "height"});
  s.width = rd.integer(img, "width", "image.width", 1, kMaxImageSize);
  s.height = rd.integer(img, "height", "image.height", 1, kMaxImageSize);

  s.camera = parse_camera(rd, root);
  s.materials = parse_materials(rd, root);
  s.lights = parse_lights(rd, root);
  s.ambient = rd.colour_or(root, "ambient", "ambient", dvec3(0.0), kMaxRadiance);
  std::map<std::string, int> mats;
  for (size_t i = 0; i < s.materials.size(); ++i) mats[s.materials[i].name] = static_cast<int>(i);

  const json& meshes = rd.array(root, "meshes", "meshes", 1);
  for (size_t i = 0; i < meshes.size(); ++i)
    s.meshes.push_back(parse_mesh(rd, meshes[i], "meshes[" + std::to_string(i) + "]", mats, options));
  return s;
}

Scene load_scene(const std::string& path) { return load_scene(path, SceneOptions{}); }

Scene load_scene(const std::string& path, const SceneOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file (expected a readable JSON file)");
  std::ostringstream os;
  os << in.rdbuf();
  return parse_scene(os.str(), path, options);
}

}  // namespace specular
