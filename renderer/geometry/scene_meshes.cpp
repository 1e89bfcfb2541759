#include "geometry/scene_meshes.h"

#include "geometry/model_file.h"
#include "geometry/transform.h"

namespace xval {

namespace {
// The shape's meshes before the object transform and the rounding.
std::vector<TriangleMesh> exactMeshes(const Shape& shape) {
  if (const auto* m = std::get_if<MeshFile>(&shape)) {
    std::vector<TriangleMesh> out;
    for (const ModelPrimitive& p : m->model->primitives) out.push_back(p.mesh);
    return out;
  }
  return {tessellateExact(shape)};
}
}  // namespace

std::vector<TriangleMesh> objectMeshes(const SceneObject& object) {
  std::vector<TriangleMesh> meshes = exactMeshes(object.shape);
  if (!object.transform.isIdentity()) {
    const Affine a = toAffine(object.transform);
    for (auto& m : meshes) m = transformed(m, a);
  }
  for (auto& m : meshes) roundToFloat(m);
  return meshes;
}

std::vector<std::string> meshNotes(const Scene& scene) {
  std::vector<std::string> out;
  for (const SceneObject& o : scene.objects)
    if (const auto* m = std::get_if<MeshFile>(&o.shape))
      out.insert(out.end(), m->model->notes.begin(), m->model->notes.end());
  return out;
}

SceneMeshes sceneMeshes(const Scene& scene) {
  SceneMeshes out;
  for (size_t k = 0; k < scene.objects.size(); ++k)
    for (TriangleMesh& m : objectMeshes(scene.objects[k])) {
      out.meshes.push_back(std::move(m));
      out.object.push_back(k);
    }
  return out;
}

}  // namespace xval
