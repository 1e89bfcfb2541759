#include "geometry/model_textures.h"

#include <memory>

#include "geometry/model_file.h"

namespace xval {

namespace {
bool fromModel(const Material& m) { return m.texture && m.texture->source == TextureSpec::Source::Model; }

// The material primitive p is shaded with under `m` (source model).
Material primitiveMaterial(const Material& m, const MeshFile& file, const ModelPrimitive& p) {
  Material out = m;
  if (!p.texture) {
    out.texture.reset();  // base_color
    return out;
  }
  TextureSpec t;
  t.source = TextureSpec::Source::Image;
  t.filter = m.texture->filter;
  if (p.texture->embedded()) {
    t.path = file.path;
    t.embedded = std::make_shared<const std::vector<std::uint8_t>>(p.texture->bytes);
  } else {
    t.path = p.texture->file;
  }
  out.texture = t;
  return out;
}
}  // namespace

bool usesModelTextures(const Scene& scene) {
  for (size_t k = 0; k < scene.objects.size(); ++k)
    if (fromModel(materialOf(scene, k))) return true;
  return false;
}

Scene resolveModelTextures(const Scene& scene) {
  if (!usesModelTextures(scene)) return scene;
  Scene out = scene;
  out.objects.clear();
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    const Material& m = materialOf(scene, k);
    const auto* file = std::get_if<MeshFile>(&o.shape);
    if (!fromModel(m) || !file) {  // the loader allows source model only on a mesh
      out.objects.push_back(o);
      continue;
    }
    for (const ModelPrimitive& p : file->model->primitives) {
      auto one = std::make_shared<Model>();
      one->file = file->model->file;
      one->format = file->model->format;
      one->files = file->model->files;
      one->primitives.push_back(p);
      SceneObject part = o;
      part.shape = MeshFile{file->path, std::move(one)};
      part.material = primitiveMaterial(m, *file, p);
      out.objects.push_back(std::move(part));
    }
  }
  // A default material of source model is now no object's (each object
  // that used it is a mesh, so it has a material of its own above): it
  // keeps its lighting model and loses the texture no renderer could load.
  if (fromModel(out.material)) out.material.texture.reset();
  return out;
}

}  // namespace xval
