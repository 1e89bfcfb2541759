// The triangles of a scene: what the reference renderer traces and what
// every exporter writes (POV-Ray mesh2, glTF buffers), made in this one
// place so that all of them receive the same float32 numbers.
//
// Per object, in the order of "objects":
//   a built-in shape (torus knot, sphere, plane): one mesh, tessellated
//     (geometry/mesh.h);
//   a model file: one mesh per primitive of the file, in the file's order
//     (geometry/model_file.h: node transforms already applied);
// then mapped by the object's transform (geometry/transform.h: positions
// by A p + o, normals by A^-T, re-wound when det A < 0) unless it is the
// identity, and rounded to float32 as the last step (roundToFloat). An
// untransformed built-in shape is exactly tessellate(shape).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"

namespace xval {

struct SceneMeshes {
  std::vector<TriangleMesh> meshes;
  std::vector<size_t> object;  // meshes[i] belongs to scene.objects[object[i]]
};

// The meshes of one object (see above).
std::vector<TriangleMesh> objectMeshes(const SceneObject& object);

// Every object's meshes, in order.
SceneMeshes sceneMeshes(const Scene& scene);

// What the model loader changed in the scene's model files (Model::notes:
// triangles dropped, geometry/degenerate_triangles.h), each object's in
// order: the same for every renderer, so each render's record and log
// carries it.
std::vector<std::string> meshNotes(const Scene& scene);

}  // namespace xval
