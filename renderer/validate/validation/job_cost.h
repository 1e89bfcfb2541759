// The order `xval validate` starts its render jobs in: the longest first,
// so that the job on the critical path (a large scene's POV-Ray job) does
// not start last (run_job.h runJobs). The order changes no result: every
// job writes its own files, and the compare step reads them in plan order.
//
// A job's cost is an estimate of its seconds on an idle core, from what
// its scene says before anything is rendered:
//
//   seconds = fixed + per_megasample x samples / 1e6 + per_megatriangle x triangles / 1e6
//
// with samples = width x height x spp and triangles as the scene's objects
// tessellate to (scene_budget.h triangleCount). The coefficients per
// renderer (kJobCosts) are fitted by eye to the job records of the
// reference set (results/validation/results.json, 2026-12-02: e.g.
// POV-Ray 1.2-2.1 s for a 256 x 256 sphere, 2.6-3.8 s for a 360 x 360
// knot of 61,440 triangles, 5.3-5.5 s at 720 x 720; the reference renderer
// 0.2-0.4 s, 0.4-0.8 s, 1.2-1.6 s). Each renderer's entry declares its own
// (renderers::Renderer::job_cost, in its file); one that declares none has
// the reference renderer's (renderers::kReferenceJobCost), which is the
// struct's default. Only their order matters: they rank the jobs.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "renderers/renderer.h"
#include "scene/scene.h"

namespace xval::validation {

// What a job's cost is estimated from.
struct JobSize {
  double samples = 0.0;    // width x height x spp
  double triangles = 0.0;  // over all objects
};

// The scene's size (its camera, spp and objects; model files as loaded).
JobSize sceneSize(const Scene& scene);

// The estimated seconds of a job of a renderer with coefficients `cost`
// (its registry entry's job_cost) on a scene of `size`.
double estimateJobSeconds(const renderers::JobCost& cost, const JobSize& size);

// The indices of `costs`, the largest cost first; equal costs keep their
// given order (so equal jobs run in plan order).
std::vector<size_t> longestFirst(const std::vector<double>& costs);

}  // namespace xval::validation
