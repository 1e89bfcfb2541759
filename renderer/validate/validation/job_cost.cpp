// The cost estimate and order of validate's render jobs (job_cost.h).
#include "validate/validation/job_cost.h"

#include <algorithm>
#include <numeric>

#include "scene_file/scene_budget.h"

namespace xval::validation {

JobSize sceneSize(const Scene& scene) {
  JobSize s;
  s.samples = double(scene.camera.width) * double(scene.camera.height) * double(scene.render.spp);
  for (const SceneObject& o : scene.objects) s.triangles += double(triangleCount(o.shape));
  return s;
}

double estimateJobSeconds(const renderers::JobCost& c, const JobSize& size) {
  return c.fixed + c.per_megasample * size.samples / 1e6 + c.per_megatriangle * size.triangles / 1e6;
}

std::vector<size_t> longestFirst(const std::vector<double>& costs) {
  std::vector<size_t> order(costs.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costs[a] > costs[b]; });
  return order;
}

}  // namespace xval::validation
