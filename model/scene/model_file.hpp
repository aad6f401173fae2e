// SPDX-License-Identifier: Apache-2.0
// Model files (OBJ, PLY, STL, 3DS, Collada, glTF and whatever else libassimp reads) as
// one scene Mesh: the `model` mesh type of the scene format (scenes/README.md).
//
// The file is read by assimp with aiProcess_Triangulate, aiProcess_JoinIdenticalVertices
// and aiProcess_PreTransformVertices (node transforms applied, instances duplicated);
// points and lines are dropped, every mesh of the file is merged into one Mesh of kind
// "model", then the triangles are fitted into the scene by ModelFit.
//
// Normals: a mesh of the file that carries normals keeps them (rotated with the model).
// Where the file has none, each vertex gets the angle-weighted average of the unit face
// normals of every triangle of the file that touches its position (vertices at exactly
// the same coordinates are one vertex for this, across meshes; weight = the triangle's
// interior angle at that vertex, so the result does not depend on how a polygon was cut
// into triangles). Triangles of zero area are dropped.
#pragma once

#include "scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace specular {

// Where the model goes: the axis-aligned bounding box of its triangles (those of
// non-zero area) is scaled uniformly so that its largest side is `size`, its centre
// moved to `center`, then the model is rotated about `center` by `rotate_deg` (about x,
// then y, then z; degrees, right-hand rule about the world axes).
struct ModelFit {
  glm::dvec3 center{0, 0, 0};
  double size = 1.0;  // finite, > 0
  glm::dvec3 rotate_deg{0, 0, 0};
};

// The rotation of ModelFit::rotate_deg, applied as `R * v`: R = Rz * Ry * Rx.
// Multiples of 90 degrees are exact (sine and cosine in {-1, 0, 1}), so a quarter turn
// keeps axis-aligned faces axis-aligned.
glm::dmat3 model_rotation(const glm::dvec3& rotate_deg);

// Loads `path` (used as given: the scene loader resolves it against the scene file's
// directory first). Throws SceneError "<path>: <reason>" for a missing or unreadable
// file, a format assimp rejects (with assimp's error string), a file without triangles
// of non-zero area, non-finite coordinates, or a bad fit.
Mesh load_model_mesh(const std::string& path, const ModelFit& fit);

}  // namespace specular
