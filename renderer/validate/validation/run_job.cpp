// The render jobs of `xval validate` (run_job.h).
#include "validate/validation/run_job.h"

#include <chrono>
#include <cstdio>
#include <mutex>

#include "files/output_folder.h"
#include "image/image.h"
#include "process/job_pool.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "scene/scene_loader.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kPreviewSide = 360;  // report images: 8-bit, at most 360 px

// Renders the job's scene and writes its EXR and preview PNG; returns the
// render's own seconds (-1: not reported). Throws on any failure.
double renderImages(const Plan& plan, const RenderJob& job, const Scene& scene, const renderers::Renderer& renderer) {
  renderers::RenderRequest request;
  request.timeout_seconds = plan.timeout_seconds;
  if (renderer.reference) {
    RenderOptions o = defaultOptions(scene);
    o.precision = Precision::Double;
    o.threads = 1;  // parallelism comes from running jobs side by side
    request.options = o;
  }
  if (renderer.external()) {
    // A fresh work folder per attempt: nothing planted or left there by
    // an earlier attempt is read or written through.
    request.work_dir = plan.dir / job.scene / (job.renderer + ".work");
    makeFreshFolder(request.work_dir);
  }
  renderers::RenderInfo info;
  Image image = renderer.render(scene, request, &info);
  writeImage(image, plan.dir / job.exr());
  writePreviewPng(image, plan.dir / job.png(), kPreviewSide);
  return info.render_seconds;
}

}  // namespace

JobRecord runJob(const Plan& plan, const RenderJob& job) {
  const fs::path cdir = plan.dir / job.scene;
  const fs::path record = plan.dir / job.record();
  JobRecord rec;
  rec.input_hash = job.input_hash;
  const auto t0 = Clock::now();
  // The case folder must be a real folder (never a link to elsewhere):
  // otherwise nothing, not even the record, is written into it.
  try {
    makeRealFolder(plan.dir, cdir);
  } catch (const std::exception& e) {
    rec.error = e.what();
    return rec;
  }
  try {
    // The record is written last: remove the old one first, so that an
    // interrupted job never leaves an "ok" beside images it did not write.
    std::error_code ec;
    if (!fs::remove(record, ec) && ec)
      throw std::runtime_error(record.string() + ": cannot remove the previous record: " + ec.message());
    Scene scene = loadScene(job.path, plan.budget);
    const std::string now_hash = inputHash(scene, job.path, job.renderer);
    if (now_hash != job.input_hash)
      throw std::runtime_error(job.path.string() + ": changed since the plan was written (input_hash " +
                               now_hash + ", the plan's is " + job.input_hash + "): plan again");
    const renderers::Renderer& renderer = renderers::registry().at(job.renderer);
    // A renderer that declares it cannot express the scene renders nothing:
    // its record says why (a verdict; compare_step.h leaves its pairs out).
    if (renderer.cannot_express) rec.not_expressible = renderer.cannot_express(scene);
    if (rec.not_expressible.empty()) rec.render_seconds = renderImages(plan, job, scene, renderer);
  } catch (const std::exception& e) {
    rec.error = e.what();
  }
  rec.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  try {
    writeRecord(plan, job, rec);
    rec.present = true;
  } catch (const std::exception& e) {
    // No record: the compare step reports the job as not run.
    rec.error = (rec.error.empty() ? std::string() : rec.error + "; ") +
                "the job's record cannot be written: " + e.what();
  }
  return rec;
}

// The jobs not yet done (all of them unless resuming), in plan order.
std::vector<size_t> jobsToRun(const Plan& plan, bool resume) {
  std::vector<size_t> todo;
  for (const auto& job : plan.jobs)
    if (!resume || !isDone(plan, job)) todo.push_back(job.index);
  return todo;
}

// Runs the given jobs, `workers` at a time (process/job_pool.h), with a
// progress line each.
void runJobs(const Plan& plan, const std::vector<size_t>& todo, int workers) {
  const auto t_start = Clock::now();
  size_t done = 0;
  std::mutex lock;
  runJobPool(todo.size(), workers, [&](size_t k) {
    const RenderJob& job = plan.jobs[todo[k]];
    // A job's exception is this job's error, and the compare step finds
    // the job not done; the other jobs go on.
    JobRecord rec;
    try {
      rec = runJob(plan, job);
    } catch (const std::exception& e) {
      rec.error = e.what();
    } catch (...) {
      rec.error = "unknown exception";
    }
    std::lock_guard<std::mutex> g(lock);
    const size_t n = ++done;
    const double el = std::chrono::duration<double>(Clock::now() - t_start).count();
    std::fprintf(stderr, "[%zu/%zu] %-32s %-9s %s %6.2f s   elapsed %.0f s, ~%.0f s left\n", n,
                 todo.size(), job.scene.c_str(), job.renderer.c_str(),
                 !rec.error.empty() ? "ERROR" : !rec.not_expressible.empty() ? "not expressible" : "ok   ",
                 rec.seconds, el, el * double(todo.size() - n) / double(n));
    if (!rec.error.empty()) std::fprintf(stderr, "  %s\n", rec.error.c_str());
    if (!rec.not_expressible.empty()) std::fprintf(stderr, "  %s\n", rec.not_expressible.c_str());
  });
}

}  // namespace xval::validation
