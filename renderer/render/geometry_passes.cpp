#include "render/geometry_passes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "camera/camera.h"
#include "geometry/model_file.h"
#include "geometry/scene_meshes.h"
#include "render/accel.h"

namespace xval {

namespace {

// Per mesh of sceneMeshes: whether it has uvs (a model primitive's
// has_uvs; a built-in shape always has them).
std::vector<bool> meshesWithUvs(const Scene& scene, const SceneMeshes& sm) {
  std::vector<bool> out(sm.meshes.size(), true);
  size_t first = 0;
  for (size_t i = 0; i < sm.meshes.size(); ++i) {
    if (i > 0 && sm.object[i] != sm.object[i - 1]) first = i;
    if (const auto* mf = std::get_if<MeshFile>(&scene.objects[sm.object[i]].shape)) {
      const size_t k = i - first;
      if (k >= mf->model->primitives.size())
        throw std::logic_error("referenceGeometryPasses: more meshes than the model's primitives");
      out[i] = mf->model->primitives[k].has_uvs;
    }
  }
  return out;
}

}  // namespace

GeometryPasses referenceGeometryPasses(const Scene& scene) {
  const SceneMeshes sm = sceneMeshes(scene);
  const std::vector<bool> uvs = meshesWithUvs(scene, sm);
  const Accel accel(sm.meshes, Precision::Double);
  const CameraRays cam(scene.camera);
  GeometryPasses out(cam.width, cam.height);
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const glm::dvec3 d = cam.direction(i + 0.5, j + 0.5);
      const Hit h = accel.intersect(cam.origin, d);
      if (!h.hit) continue;
      const size_t p = size_t(j) * cam.width + i;
      const TriangleMesh& m = sm.meshes[h.mesh];
      const glm::u32vec3 t = m.triangles[h.triangle];
      const double b0 = 1.0 - h.b1 - h.b2;
      const glm::dvec2 uv = b0 * m.uvs[t.x] + h.b1 * m.uvs[t.y] + h.b2 * m.uvs[t.z];
      out.hit[p] = 1.0f;
      out.depth[p] = float(h.t * glm::dot(d, cam.forward));
      out.has_uv[p] = uvs[h.mesh] ? 1.0f : 0.0f;
      out.u[p] = uvs[h.mesh] ? float(uv.x) : 0.0f;
      out.v[p] = uvs[h.mesh] ? float(uv.y) : 0.0f;
      out.edge[p] = float(std::min({b0, h.b1, h.b2}));
      out.object[p] = int32_t(sm.object[h.mesh]);
    }
  return out;
}

Image toImage(const GeometryPasses& g) {
  Image img(g.width, g.height, false);
  img.raw.assign(g.size() * 3, 0.0f);
  for (size_t p = 0; p < g.size(); ++p) {
    float* px = &img.rgba[p * 4];
    px[0] = g.u[p];
    px[1] = g.v[p];
    px[2] = g.depth[p];
    px[3] = g.hit[p];
    img.raw[p * 3 + 0] = float(g.object[p] + 1);
    img.raw[p * 3 + 1] = g.has_uv[p];
    img.raw[p * 3 + 2] = g.edge[p];
  }
  return img;
}

Image passesPreview(const GeometryPasses& g) {
  Image img(g.width, g.height, false);
  auto wrap = [](float x) { return x - std::floor(x); };
  float near = INFINITY, far = -INFINITY;
  for (size_t p = 0; p < g.size(); ++p)
    if (g.hit[p] > 0.5f) near = std::min(near, g.depth[p]), far = std::max(far, g.depth[p]);
  for (size_t p = 0; p < g.size(); ++p) {
    float* px = &img.rgba[p * 4];
    const bool hit = g.hit[p] > 0.5f, uv = g.has_uv[p] > 0.5f;
    const float depth01 = far > near ? (g.depth[p] - near) / (far - near) : 0.0f;
    px[0] = hit && uv ? wrap(g.u[p]) : 0.0f;
    px[1] = hit && uv ? wrap(g.v[p]) : 0.0f;
    px[2] = hit ? 1.0f - 0.75f * depth01 : 0.0f;
    px[3] = hit ? 1.0f : 0.0f;
  }
  return img;
}

GeometryPasses geometryPassesFromImage(const Image& img) {
  if (img.raw.size() != size_t(img.width) * img.height * 3)
    throw std::runtime_error("geometry passes: the image has no raw channels (object, has_uv, edge)");
  GeometryPasses g(img.width, img.height);
  for (size_t p = 0; p < g.size(); ++p) {
    const float* px = &img.rgba[p * 4];
    g.u[p] = px[0];
    g.v[p] = px[1];
    g.depth[p] = px[2];
    g.hit[p] = px[3];
    g.object[p] = int32_t(img.raw[p * 3 + 0]) - 1;
    g.has_uv[p] = img.raw[p * 3 + 1];
    g.edge[p] = img.raw[p * 3 + 2];
  }
  return g;
}

}  // namespace xval
