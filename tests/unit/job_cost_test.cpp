// validate/validation/job_cost.h: the jobs' cost estimates rank a large
// scene's POV-Ray job first, and longestFirst orders by cost, ties in the
// given order.
#include <gtest/gtest.h>

#include <vector>

#include "renderers/registry.h"
#include "validate/validation/job_cost.h"

using namespace xval;
using namespace xval::validation;

TEST(JobCost, LongestFirstKeepsTheGivenOrderOfEqualCosts) {
  EXPECT_EQ(longestFirst({1.0, 5.0, 2.0, 5.0, 0.5}), (std::vector<size_t>{1, 3, 2, 0, 4}));
  EXPECT_EQ(longestFirst({}), std::vector<size_t>{});
  EXPECT_EQ(longestFirst({3.0, 3.0, 3.0}), (std::vector<size_t>{0, 1, 2}));
}

TEST(JobCost, EstimateGrowsWithSamplesAndTriangles) {
  const JobSize small{256.0 * 256.0, 2000.0}, knot{720.0 * 720.0, 61440.0};
  for (const std::string& id : renderers::registry().ids()) {
    const renderers::JobCost& c = renderers::registry().at(id).job_cost;
    EXPECT_GT(estimateJobSeconds(c, knot), estimateJobSeconds(c, small)) << id;
    EXPECT_GT(estimateJobSeconds(c, small), 0.0) << id;
  }
  // A renderer that declares no cost is estimated as the reference renderer.
  EXPECT_DOUBLE_EQ(estimateJobSeconds(renderers::registry().at("golden").job_cost, knot),
                   estimateJobSeconds(renderers::registry().at("reference").job_cost, knot));
}

// The reference set's critical path: Table 2's 720 x 720 knot's POV-Ray job
// is the longest single job, then the 360 x 360 knots' POV-Ray job, while
// in plan order (scenes sorted by name) it comes last.
TEST(JobCost, TheLargeKnotsPovRayJobRanksFirst) {
  Scene table2, fig1, sphere;
  table2.camera.width = table2.camera.height = 720;
  table2.objects = {SceneObject{TorusKnot{}}};
  std::get<TorusKnot>(table2.objects[0].shape).segments_along = 768;
  std::get<TorusKnot>(table2.objects[0].shape).segments_around = 40;
  fig1 = table2;
  fig1.camera.width = fig1.camera.height = 360;
  sphere.camera.width = sphere.camera.height = 256;
  sphere.objects = {SceneObject{UvSphere{}}};
  EXPECT_DOUBLE_EQ(sceneSize(table2).samples, 720.0 * 720.0);
  EXPECT_DOUBLE_EQ(sceneSize(table2).triangles, 2.0 * 768 * 40);
  struct Job {
    const char* renderer;
    const Scene* scene;
  };
  // In plan order (scenes sorted by name, then renderers): the knot last.
  const std::vector<Job> jobs = {{"reference", &fig1},   {"povray", &fig1},  {"reference", &sphere},
                                 {"povray", &sphere},    {"reference", &table2}, {"povray", &table2}};
  std::vector<double> cost;
  for (const Job& j : jobs)
    cost.push_back(estimateJobSeconds(renderers::registry().at(j.renderer).job_cost, sceneSize(*j.scene)));
  EXPECT_EQ(longestFirst(cost), (std::vector<size_t>{5, 1, 4, 3, 0, 2}));
}
