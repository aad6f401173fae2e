// SPDX-License-Identifier: Apache-2.0
// Model files through libassimp into one scene Mesh. See model_file.hpp for the contract
// and scenes/README.md for the `model` mesh fields.
#include "model_file.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

namespace specular {

namespace fs = std::filesystem;
using glm::dvec3;

namespace {

// Sine and cosine of an angle in degrees, exact at multiples of 90 degrees: std::cos(pi/2)
// is 6e-17, which would tilt a quarter-turned flat face by that much.
void sin_cos_deg(double deg, double& s, double& c) {
  const double r = std::fmod(deg, 360.0);  // exact: fmod never rounds
  if (r == 0.0) {
    s = 0, c = 1;
  } else if (r == 90.0 || r == -270.0) {
    s = 1, c = 0;
  } else if (r == 180.0 || r == -180.0) {
    s = 0, c = -1;
  } else if (r == 270.0 || r == -90.0) {
    s = -1, c = 0;
  } else {
    const double rad = r * (std::numbers::pi / 180.0);
    s = std::sin(rad);
    c = std::cos(rad);
  }
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw SceneError(path + ": " + reason);
}

[[noreturn]] void assimp_fail(const std::string& path, const Assimp::Importer& importer) {
  std::string err = importer.GetErrorString();
  while (!err.empty() && std::isspace(static_cast<unsigned char>(err.back()))) err.pop_back();  // PLY's ends in a space
  if (err.empty()) err = "no reason given";
  fail(path, "assimp cannot read the model file: " + err);
}

const char* const kNoTriangles = "the model file has no triangles (no meshes, or only points and lines)";

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

dvec3 to_dvec3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

}  // namespace

glm::dmat3 model_rotation(const dvec3& deg) {
  double sx, cx, sy, cy, sz, cz;
  sin_cos_deg(deg.x, sx, cx);
  sin_cos_deg(deg.y, sy, cy);
  sin_cos_deg(deg.z, sz, cz);
  // glm matrices are column-major: m[column][row].
  glm::dmat3 rx(1.0), ry(1.0), rz(1.0);
  rx[1][1] = cx, rx[2][1] = -sx, rx[1][2] = sx, rx[2][2] = cx;
  ry[0][0] = cy, ry[2][0] = sy, ry[0][2] = -sy, ry[2][2] = cy;
  rz[0][0] = cz, rz[1][0] = -sz, rz[0][1] = sz, rz[1][1] = cz;
  return rz * ry * rx;
}

Mesh load_model_mesh(const std::string& path, const ModelFit& fit) {
  {
    std::ostringstream os;
    os.precision(17);
    if (!(std::isfinite(fit.size) && fit.size > 0)) {
      os << "the fit size must be a finite number > 0, got " << fit.size;
      fail(path, os.str());
    }
    if (!finite(fit.center)) fail(path, "the fit centre must be 3 finite numbers");
    if (!finite(fit.rotate_deg)) fail(path, "the rotation must be 3 finite numbers of degrees");
  }

  // Checked before assimp sees the path: its own message for a missing file is less
  // precise, and a FIFO or a device such as /dev/zero would make it block or read forever.
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) fail(path, "cannot read the model file: no such file");
  if (!fs::is_regular_file(st)) fail(path, "cannot read the model file: not a regular file");
  if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot read the model file: it cannot be opened for reading");

  Assimp::Importer importer;
  // Points and lines are dropped below (faces with fewer than 3 indices). Neither
  // aiProcess_SortByPType's removal nor aiProcess_ValidateDataStructure is used: both turn
  // a point cloud or a line-only file into an import failure ("Mesh contains no faces")
  // instead of the "no triangles" it is; the indices are range-checked here instead.
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices;
  // Read first, post-process second: aiProcess_PreTransformVertices refuses a scene whose
  // meshes have no faces ("all meshes are orphaned"), so a point cloud is recognized
  // before it runs.
  const aiScene* sc = importer.ReadFile(path, 0);
  if (sc == nullptr) assimp_fail(path, importer);
  bool any_polygon = false;
  for (unsigned mi = 0; mi < sc->mNumMeshes && !any_polygon; ++mi)
    for (unsigned f = 0; f < sc->mMeshes[mi]->mNumFaces && !any_polygon; ++f)
      any_polygon = sc->mMeshes[mi]->mFaces[f].mNumIndices >= 3;
  if (!any_polygon) fail(path, kNoTriangles);
  sc = importer.ApplyPostProcessing(flags);
  if (sc == nullptr) assimp_fail(path, importer);

  // Triangles as (mesh, local vertex) references, and every vertex's position class:
  // positions with exactly equal coordinates (after the node transforms) are one position,
  // across meshes, so that generated normals are smooth where meshes or UV seams meet.
  struct Tri {
    unsigned mesh;
    std::array<unsigned, 3> v;
  };
  std::vector<Tri> tris;
  std::vector<std::vector<int>> pos_of(sc->mNumMeshes);  // mesh, local vertex -> position id
  std::vector<dvec3> pos;                                // file coordinates per position id
  std::map<std::array<double, 3>, int> pos_id;
  for (unsigned mi = 0; mi < sc->mNumMeshes; ++mi) {
    const aiMesh* m = sc->mMeshes[mi];
    pos_of[mi].assign(m->mNumVertices, -1);
    for (unsigned f = 0; f < m->mNumFaces; ++f) {
      const aiFace& face = m->mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or a line: nothing to rasterize
      Tri t{mi, {}};
      for (int k = 0; k < 3; ++k) {
        const unsigned vi = face.mIndices[k];
        if (vi >= m->mNumVertices) fail(path, "a face refers to a vertex the mesh does not have");
        t.v[k] = vi;
        if (pos_of[mi][vi] < 0) {
          const dvec3 p = to_dvec3(m->mVertices[vi]);
          if (!finite(p)) fail(path, "a triangle has a vertex with non-finite coordinates");
          // +0.0 folds -0.0 into 0.0 so that both are one position.
          const std::array<double, 3> key{p.x + 0.0, p.y + 0.0, p.z + 0.0};
          auto [it, fresh] = pos_id.try_emplace(key, static_cast<int>(pos.size()));
          if (fresh) pos.push_back(p);
          pos_of[mi][vi] = it->second;
        }
      }
      tris.push_back(t);
    }
  }
  if (tris.empty()) fail(path, kNoTriangles);
  if (pos.size() > static_cast<size_t>(std::numeric_limits<int>::max()) / 2)
    fail(path, "the model has too many vertices");

  // Triangles of zero area carry no normal and cover no pixel: dropped. Face normals and
  // angles are taken in the file's coordinates: the fit is a similarity (uniform scale,
  // rotation), which keeps angles and turns normals by the rotation alone, and a tiny
  // fit_size cannot underflow them there.
  std::vector<Tri> kept;
  std::vector<dvec3> face_n;
  kept.reserve(tris.size());
  auto at = [&](const Tri& t, int k) -> const dvec3& {
    return pos[static_cast<size_t>(pos_of[t.mesh][t.v[static_cast<size_t>(k)]])];
  };
  for (const Tri& t : tris) {
    const dvec3 n = glm::cross(at(t, 1) - at(t, 0), at(t, 2) - at(t, 0));
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) continue;
    kept.push_back(t);
    face_n.push_back(n / len);
  }
  if (kept.empty()) fail(path, "the model file has no triangles of non-zero area");

  // The fit: bounding box of the vertices of the kept triangles only (dropped points,
  // lines and degenerate triangles do not move the model).
  dvec3 lo = at(kept[0], 0), hi = lo;
  for (const Tri& t : kept)
    for (int k = 0; k < 3; ++k) lo = glm::min(lo, at(t, k)), hi = glm::max(hi, at(t, k));
  const dvec3 extent = hi - lo;
  const double side = std::max(extent.x, std::max(extent.y, extent.z));
  if (!(side > 0.0) || !std::isfinite(side)) fail(path, "the model's extent is not a finite number, so it cannot be fitted");
  const double scale = fit.size / side;
  const dvec3 box_center = 0.5 * (lo + hi);
  const glm::dmat3 rot = model_rotation(fit.rotate_deg);
  std::vector<dvec3> world(pos.size());
  for (size_t i = 0; i < pos.size(); ++i) world[i] = fit.center + rot * (scale * (pos[i] - box_center));

  // Generated normals for every position: angle-weighted sum of the unit face normals
  // (interior angle at the vertex by atan2(|u x v|, u . v), accurate at any angle).
  std::vector<dvec3> gen(pos.size(), dvec3(0.0));
  std::vector<int> first_face(pos.size(), -1);
  for (size_t f = 0; f < kept.size(); ++f) {
    const Tri& t = kept[f];
    for (int k = 0; k < 3; ++k) {
      const size_t p = static_cast<size_t>(pos_of[t.mesh][t.v[static_cast<size_t>(k)]]);
      const dvec3 u = at(t, (k + 1) % 3) - pos[p];
      const dvec3 v = at(t, (k + 2) % 3) - pos[p];
      const double angle = std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
      gen[p] += angle * face_n[f];
      if (first_face[p] < 0) first_face[p] = static_cast<int>(f);
    }
  }
  for (size_t p = 0; p < pos.size(); ++p) {
    if (first_face[p] < 0) continue;  // only on dropped triangles: not in the output
    const double len = glm::length(gen[p]);
    // A sum that cancels (a vertex of a two-sided sheet): the first face's normal.
    const dvec3 n = len > 0.0 && std::isfinite(len) ? gen[p] / len : face_n[static_cast<size_t>(first_face[p])];
    gen[p] = glm::normalize(rot * n);
  }

  // Output vertices: a mesh with normals keeps one vertex per (mesh, vertex) as assimp
  // joined them, with its own normal; a mesh without normals gets one vertex per position.
  Mesh out;
  out.kind = "model";
  std::vector<std::vector<int>> out_of_local(sc->mNumMeshes);
  std::vector<int> out_of_pos(pos.size(), -1);
  auto vertex = [&](const Tri& t, int k) -> int {
    const aiMesh* m = sc->mMeshes[t.mesh];
    const unsigned vi = t.v[static_cast<size_t>(k)];
    const int p = pos_of[t.mesh][vi];
    if (m->HasNormals()) {
      auto& map = out_of_local[t.mesh];
      if (map.empty()) map.assign(m->mNumVertices, -1);
      if (map[vi] < 0) {
        dvec3 n = rot * to_dvec3(m->mNormals[vi]);
        const double len = glm::length(n);
        // A zero or non-finite normal in the file (it happens: glTF test models carry
        // them): the generated normal instead of an undefined shade.
        n = len > 0.0 && std::isfinite(len) ? n / len : gen[static_cast<size_t>(p)];
        map[vi] = static_cast<int>(out.positions.size());
        out.positions.push_back(world[static_cast<size_t>(p)]);
        out.normals.push_back(n);
      }
      return map[vi];
    }
    int& o = out_of_pos[static_cast<size_t>(p)];
    if (o < 0) {
      o = static_cast<int>(out.positions.size());
      out.positions.push_back(world[static_cast<size_t>(p)]);
      out.normals.push_back(gen[static_cast<size_t>(p)]);
    }
    return o;
  };
  out.triangles.reserve(kept.size());
  for (const Tri& t : kept) out.triangles.push_back({vertex(t, 0), vertex(t, 1), vertex(t, 2)});
  return out;
}

}  // namespace specular
