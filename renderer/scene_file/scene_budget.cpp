#include "scene_file/scene_budget.h"

#include <cmath>
#include <limits>

#include "geometry/model_file.h"
#include "scene/json_reader.h"
#include "scene/scene.h"

namespace xval {

Budget unlimitedBudget() {
  const long long big = std::numeric_limits<long long>::max() / 4;
  return {big, big, big};
}

long long triangleCount(const Shape& s) {
  if (const auto* k = std::get_if<TorusKnot>(&s)) return 2ll * k->segments_along * k->segments_around;
  if (const auto* u = std::get_if<UvSphere>(&s))  // the poles' rows have one triangle per quad
    return 2ll * u->segments_longitude * (u->segments_latitude - 1);
  if (const auto* m = std::get_if<MeshFile>(&s)) return m->model ? m->model->triangleCount() : 0;
  return 2;
}

namespace {
int scaled(int segments, double factor) { return int(std::lround(segments * factor)); }
}  // namespace

void checkBudget(const Scene& scene, int spp, const Budget& budget, double f) {
  const std::string file = scene.source_file.string();
  long long triangles = 0, largest = -1;
  size_t largest_at = 0;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    Shape s = scene.objects[k].shape;
    if (f != 1.0) {
      if (auto* t = std::get_if<TorusKnot>(&s))
        t->segments_along = scaled(t->segments_along, f), t->segments_around = scaled(t->segments_around, f);
      if (auto* u = std::get_if<UvSphere>(&s))
        u->segments_longitude = scaled(u->segments_longitude, f), u->segments_latitude = scaled(u->segments_latitude, f);
    }
    const long long n = triangleCount(s);
    triangles += n;
    if (n > largest) largest = n, largest_at = k;
  }
  const std::string tess = f != 1.0 ? " at tessellation x" + std::to_string(f) : "";
  if (triangles > budget.max_triangles)
    throw SceneError(file + ": objects: " + std::to_string(scene.objects.size()) + " objects tessellate to " +
                     std::to_string(triangles) + " triangles in all" + tess + " (the largest, objects[" +
                     std::to_string(largest_at) + "], to " + std::to_string(largest) + "); the limit is " +
                     std::to_string(budget.max_triangles) + " (raise it with --max-triangles N or --allow-large)");
  const long long pixels = (long long)scene.camera.width * scene.camera.height;
  const long long samples = pixels * spp;
  if (samples > budget.max_samples)
    throw SceneError(file + ": render.spp: width x height x spp = " + std::to_string(scene.camera.width) + " x " +
                     std::to_string(scene.camera.height) + " x " + std::to_string(spp) + " = " +
                     std::to_string(samples) + " samples; the limit is " + std::to_string(budget.max_samples) +
                     " (raise it with --max-samples N or --allow-large)");
  const double mb = (double(kBytesPerTriangle) * double(triangles) + double(kBytesPerPixel) * double(pixels)) /
                    (1024.0 * 1024.0);
  if (mb > double(budget.max_memory_mb))
    throw SceneError(file + ": camera.width: the render would need about " + std::to_string(std::llround(mb)) +
                     " MiB (" + std::to_string(kBytesPerPixel) + " bytes x " + std::to_string(pixels) + " pixels + " +
                     std::to_string(kBytesPerTriangle) + " bytes x " + std::to_string(triangles) +
                     " triangles); the limit is " + std::to_string(budget.max_memory_mb) +
                     " MiB (raise it with --max-memory-mb N or --allow-large)");
}

}  // namespace xval
