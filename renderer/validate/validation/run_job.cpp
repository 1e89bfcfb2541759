// The render jobs of `xval validate` (run_job.h).
#include "validate/validation/run_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdint>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "files/output_folder.h"
#include "image/image.h"
#include "process/job_pool.h"
#include "geometry/scene_meshes.h"
#include "render/geometry_passes.h"
#include "render/renderer.h"
#include "validate/common/reference_job.h"
#include "validate/validation/job_cost.h"
#include "renderers/job_export.h"
#include "renderers/registry.h"
#include "scene_file/scene_loader.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The render request of a job; an outside tool's work folder is made
// fresh: nothing planted or left there by an earlier attempt is read or
// written through.
renderers::RenderRequest requestFor(const Plan& plan, const RenderJob& job, const Scene& scene,
                                    const renderers::Renderer& renderer) {
  renderers::RenderRequest request;
  request.timeout_seconds = plan.timeout_seconds;
  if (renderer.reference) {
    request.options = referenceJobOptions(scene);
  }
  if (renderer.external()) {
    request.export_key = exportInputsKey(scene, job.path);
    request.work_dir = plan.dir / job.scene / (job.renderer + ".work");
    makeFreshFolder(request.work_dir);
  }
  return request;
}

// The job's images: its EXR and preview PNG. A geometry check's job
// (plan.h) first writes the reference's passes of the same scene beside
// them, and its preview is a picture of its passes (passesPreview).
// With `images`, the EXR as read back is left there for the case's compare
// (image_handoff.h), once the preview is written too.
void writeImages(const Plan& plan, const RenderJob& job, const Scene& scene, const Image& image,
                 ImageHandoff* images) {
  const renderers::Renderer& renderer = renderers::registry().at(job.renderer);
  if (renderer.geometry_passes) {
    writeImage(toImage(referenceGeometryPasses(scene)), plan.dir / job.reference_passes());
    writeImage(image, plan.dir / job.exr());
    writePreviewPng(passesPreview(geometryPassesFromImage(image)), plan.dir / job.png(), kPreviewSide);
    return;
  }
  Image read_back;
  writeImage(image, plan.dir / job.exr(), kRenderExrCompression, images ? &read_back : nullptr);
  writePreviewPng(image, plan.dir / job.png(), kPreviewSide);
  if (images) images->put(plan.dir / job.exr(), std::move(read_back));
}

// A job between its start and its record.
struct StartedJob {
  JobRecord rec;
  Clock::time_point t0;
  std::optional<Scene> scene;  // set while it is still to be rendered
  renderers::RenderRequest request;  // its render's (with the export, when its renderer exports)
  bool no_record = false;      // its case folder was refused: nothing is written
};

// Everything before the render: the case folder, the old record removed,
// the scene loaded and checked against the plan, the request, the
// renderer's refusal, decided from the export the render then reads
// (renderers/job_export.h: one export a job).
StartedJob startJob(const Plan& plan, const RenderJob& job) {
  StartedJob s;
  s.rec.input_hash = job.input_hash;
  s.t0 = Clock::now();
  const fs::path cdir = plan.dir / job.scene;
  const fs::path record = plan.dir / job.record();
  // The case folder must be a real folder (never a link to elsewhere):
  // otherwise nothing, not even the record, is written into it.
  try {
    makeRealFolder(plan.dir, cdir);
  } catch (const std::exception& e) {
    s.rec.error = e.what();
    s.no_record = true;
    return s;
  }
  try {
    // The record is written last: remove the old one first, so that an
    // interrupted job never leaves an "ok" beside images it did not write.
    std::error_code ec;
    if (!fs::remove(record, ec) && ec)
      throw std::runtime_error(record.string() + ": cannot remove the previous record: " + ec.message());
    Scene scene = loadScene(job.path, plan.budget);
    s.rec.notes = meshNotes(scene);
    const std::string now_hash = inputHash(scene, job.path, job.renderer);
    if (now_hash != job.input_hash)
      throw std::runtime_error(job.path.string() + ": changed since the plan was written (input_hash " +
                               now_hash + ", the plan's is " + job.input_hash + "): plan again");
    const renderers::Renderer& renderer = renderers::registry().at(job.renderer);
    // A renderer that declares it cannot express the scene renders nothing:
    // its record says why (a verdict; compare_step.h leaves its pairs out).
    // (Through the export cache: the refusal of a scene checked before is
    // read back, renderers/export_cache.h.)
    renderers::RenderRequest request = requestFor(plan, job, scene, renderer);
    s.rec.not_expressible = renderers::refuseOrExport(renderer, scene, request);
    if (s.rec.not_expressible.empty()) {
      s.scene = std::move(scene);
      s.request = std::move(request);
    } else if (!request.work_dir.empty()) {
      // What the exporter wrote before it refused is no export.
      std::error_code ec;
      fs::remove_all(request.work_dir, ec);
    }
  } catch (const std::exception& e) {
    s.rec.error = e.what();
  }
  return s;
}

// The record, written last; `seconds` counts from the job's start.
JobRecord endJob(const Plan& plan, const RenderJob& job, const StartedJob& s) {
  JobRecord rec = s.rec;
  if (s.no_record) return rec;
  rec.seconds = std::chrono::duration<double>(Clock::now() - s.t0).count();
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

}  // namespace

JobRecord runJob(const Plan& plan, const RenderJob& job, ImageHandoff* images) {
  StartedJob s = startJob(plan, job);
  if (s.scene) {
    try {
      const renderers::Renderer& renderer = renderers::registry().at(job.renderer);
      renderers::RenderInfo info;
      const Image image = renderer.render(*s.scene, s.request, &info);
      writeImages(plan, job, *s.scene, image, images);
      s.rec.setToolTimes(info);
    } catch (const std::exception& e) {
      s.rec.error = e.what();
    }
  }
  return endJob(plan, job, s);
}

std::vector<JobRecord> runJobBatch(const Plan& plan, const std::vector<size_t>& jobs, const JobDone& job_done,
                                   ImageHandoff* images) {
  std::vector<StartedJob> started;
  std::vector<renderers::BatchItem> items;
  std::vector<size_t> item_of;  // started[k]'s item, or SIZE_MAX for none
  std::vector<size_t> job_of;   // an item's k in started
  const renderers::Renderer* renderer = nullptr;
  // The items point at the started jobs' scenes: `started` never reallocates.
  started.reserve(jobs.size());
  for (size_t index : jobs) {
    const RenderJob& job = plan.jobs.at(index);
    started.push_back(startJob(plan, job));
    StartedJob& s = started.back();
    item_of.push_back(SIZE_MAX);
    if (!s.scene) continue;
    try {
      const renderers::Renderer& r = renderers::registry().at(job.renderer);
      if (!r.render_batch) throw std::invalid_argument("runJobBatch: " + r.id + " renders no batches");
      if (renderer && renderer != &r)
        throw std::invalid_argument("runJobBatch: the jobs of a batch must share their renderer (" +
                                    renderer->id + ", " + r.id + ")");
      renderer = &r;
      items.push_back({&*s.scene, s.request});
      item_of.back() = items.size() - 1;
      job_of.push_back(started.size() - 1);
    } catch (const std::exception& e) {
      s.rec.error = e.what();
    }
  }
  // A job ends (its images and record written) once, as soon as its
  // outcome is final: for a batch item possibly while the batch renders on.
  std::vector<JobRecord> records(started.size());
  std::vector<char> ended(started.size(), 0);
  auto end = [&](size_t k, const renderers::BatchOutcome* o, const std::string& batch_error) {
    StartedJob& s = started[k];
    const RenderJob& job = plan.jobs.at(jobs[k]);
    if (item_of[k] != SIZE_MAX) {
      try {
        if (!batch_error.empty()) throw std::runtime_error(batch_error);
        if (!o->image) throw std::runtime_error(o->error);
        writeImages(plan, job, *s.scene, *o->image, images);
        s.rec.setToolTimes(o->info);
      } catch (const std::exception& e) {
        s.rec.error = e.what();
      }
    }
    records[k] = endJob(plan, job, s);
    ended[k] = 1;
    if (job_done) job_done(k, records[k]);
  };
  std::vector<renderers::BatchOutcome> outcomes;
  std::string batch_error;
  if (!items.empty()) {
    try {
      outcomes = renderer->render_batch(items, [&](size_t item, const renderers::BatchOutcome& o) {
        if (item < job_of.size() && !ended[job_of[item]]) end(job_of[item], &o, "");
      });
      if (outcomes.size() != items.size())
        throw std::runtime_error(renderer->id + ": the batch returned " + std::to_string(outcomes.size()) +
                                 " outcomes for " + std::to_string(items.size()) + " scenes");
    } catch (const std::exception& e) {
      batch_error = e.what();
    }
  }
  for (size_t k = 0; k < started.size(); ++k)
    if (!ended[k]) end(k, item_of[k] != SIZE_MAX && batch_error.empty() ? &outcomes[item_of[k]] : nullptr, batch_error);
  return records;
}

// The jobs not yet done (all of them unless resuming), in plan order.
std::vector<size_t> jobsToRun(const Plan& plan, bool resume) {
  std::vector<size_t> todo;
  for (const auto& job : plan.jobs)
    if (!resume || !isDone(plan, job)) todo.push_back(job.index);
  return todo;
}

namespace {

// The pool's tasks: the batches (each the jobs of one renderer that renders
// batches) and one task per other job, longest first (job_cost.h).
struct Task {
  std::vector<size_t> jobs;  // plan indices
  bool batch = false;        // one renderer's jobs in one outside process (runJobBatch)
};

// A job's renderer's cost coefficients (a renderer the registry lacks
// fails its job when it runs; its cost only places it in the order).
renderers::JobCost jobCost(const std::string& id) {
  const renderers::Renderer* r = renderers::registry().find(id);
  return r ? r->job_cost : renderers::kReferenceJobCost;
}

std::vector<Task> runTasks(const Plan& plan, const std::vector<size_t>& todo, const RunSettings& settings) {
  std::vector<Task> tasks;
  // Per renderer that renders batches: its jobs, in plan order.
  std::vector<std::pair<std::string, std::vector<size_t>>> by_renderer;
  for (size_t index : todo) {
    const RenderJob& job = plan.jobs.at(index);
    const renderers::Renderer* r = renderers::registry().find(job.renderer);
    if (settings.batch == 1 || !r || !r->render_batch) {
      tasks.push_back({{index}, false});
      continue;
    }
    auto it = std::find_if(by_renderer.begin(), by_renderer.end(),
                           [&](const auto& e) { return e.first == job.renderer; });
    if (it == by_renderer.end()) it = by_renderer.insert(by_renderer.end(), {job.renderer, {}});
    it->second.push_back(index);
  }
  std::vector<Task> batched;
  for (const auto& [id, jobs] : by_renderer) {
    // Automatic: each worker gets a share, in batches of at most kMaxBatch.
    const size_t workers = size_t(std::max(1, settings.workers));
    const size_t size = settings.batch > 0 ? settings.batch
                                           : std::clamp<size_t>((jobs.size() + workers - 1) / workers, 1, kMaxBatch);
    for (size_t at = 0; at < jobs.size(); at += size)
      batched.push_back({{jobs.begin() + long(at), jobs.begin() + long(std::min(jobs.size(), at + size))}, true});
  }
  // Ties keep this order: the batches, then the single jobs, in plan order.
  batched.insert(batched.end(), tasks.begin(), tasks.end());
  tasks = std::move(batched);
  // Each scene's size once (a scene that does not load is estimated at its
  // renderer's fixed cost: its job fails and reports why).
  std::map<std::string, JobSize> sizes;
  for (size_t index : todo) {
    const RenderJob& job = plan.jobs.at(index);
    if (sizes.count(job.scene)) continue;
    JobSize size;
    try {
      size = sceneSize(loadScene(job.path, plan.budget));
    } catch (const std::exception&) {
    }
    sizes[job.scene] = size;
  }
  std::vector<double> cost(tasks.size(), 0.0);
  for (size_t t = 0; t < tasks.size(); ++t)
    for (size_t index : tasks[t].jobs)
      cost[t] += estimateJobSeconds(jobCost(plan.jobs.at(index).renderer), sizes.at(plan.jobs.at(index).scene));
  std::vector<Task> ordered;
  for (size_t t : longestFirst(cost)) ordered.push_back(std::move(tasks[t]));
  return ordered;
}

}  // namespace

// Runs the given jobs (process/job_pool.h), with a progress line each.
std::vector<JobRecord> runJobs(const Plan& plan, const std::vector<size_t>& todo, const RunSettings& settings,
                               const AfterCase* after_case) {
  const auto t_start = Clock::now();
  ImageHandoff* const images = after_case ? after_case->images : nullptr;
  size_t done = 0;
  std::mutex lock;
  std::vector<JobRecord> out(todo.size());
  std::vector<size_t> position(plan.jobs.size(), SIZE_MAX);  // a job's place in todo
  for (size_t k = 0; k < todo.size(); ++k) position.at(todo[k]) = k;
  const std::vector<Task> tasks = runTasks(plan, todo, settings);
  // Per scene: its jobs of `todo` not ended yet (after_case runs at 0).
  std::vector<size_t> scene_of(plan.jobs.size(), SIZE_MAX), pending(plan.scenes.size(), 0);
  for (size_t k = 0; k < plan.scenes.size(); ++k)
    for (size_t j : sceneJobs(plan, k)) scene_of.at(j) = k;
  for (size_t index : todo) ++pending.at(scene_of.at(index));
  // A scene's notes (the same in each of its records) are printed once.
  std::vector<char> noted(plan.scenes.size(), 0);
  const double capacity = double(std::max(1, settings.workers));
  auto weightOf = [&](const Task& task) {
    if (!settings.by_load) return 1.0;
    const renderers::Renderer* r = renderers::registry().find(plan.jobs.at(task.jobs.front()).renderer);
    return r ? std::clamp(r->cpu_share, 1.0 / 16.0, 1.0) : 1.0;
  };
  WeightedTaskQueue queue(capacity);
  // Enough threads for the most tasks that can run at once.
  double lightest = after_case ? std::min(after_case->weight, capacity) : capacity;
  for (const auto& task : tasks) lightest = std::min(lightest, weightOf(task));
  const size_t threads = size_t(std::max(1.0, std::floor(capacity / lightest + 1e-9)));
  auto queueAfterCase = [&](size_t k, bool urgent) {
    queue.push(after_case->weight, [&, k] { after_case->run(k); }, urgent);
  };
  for (const Task& t : tasks) {
    queue.push(weightOf(t), [&, &task = t.jobs, batch = t.batch] {
      // A job's record: kept, its progress line printed, and its case
      // compared when it was the case's last job (for a batch, as each
      // scene ends, while the batch renders on).
      auto recordDone = [&](size_t index, const JobRecord& rec) {
        bool ready = false;
        {
          std::lock_guard<std::mutex> g(lock);
          const RenderJob& job = plan.jobs[index];
          out.at(position.at(index)) = rec;
          const size_t n = ++done;
          const double el = std::chrono::duration<double>(Clock::now() - t_start).count();
          std::fprintf(stderr, "[%zu/%zu] %-32s %-9s %s %6.2f s   elapsed %.0f s, ~%.0f s left\n", n,
                       todo.size(), job.scene.c_str(), job.renderer.c_str(),
                       !rec.error.empty() ? "ERROR" : !rec.not_expressible.empty() ? "not expressible" : "ok   ",
                       rec.seconds, el, el * double(todo.size() - n) / double(n));
          if (!rec.error.empty()) std::fprintf(stderr, "  %s\n", rec.error.c_str());
          if (!rec.not_expressible.empty()) std::fprintf(stderr, "  %s\n", rec.not_expressible.c_str());
          if (!std::exchange(noted.at(scene_of.at(index)), 1))
            for (const std::string& n : rec.notes) std::fprintf(stderr, "  note: %s\n", n.c_str());
          ready = --pending.at(scene_of.at(index)) == 0;
        }
        if (after_case && ready) queueAfterCase(scene_of.at(index), true);
      };
      // A job's exception is this job's error, and the compare step finds
      // the job not done; the other jobs go on.
      std::vector<char> recorded(task.size(), 0);
      auto failRest = [&](const std::string& error) {
        for (size_t k = 0; k < task.size(); ++k) {
          if (recorded[k]) continue;
          JobRecord rec;
          rec.error = error;
          recordDone(task[k], rec);
        }
      };
      try {
        if (batch) {
          runJobBatch(
              plan, task,
              [&](size_t k, const JobRecord& rec) {
                recorded.at(k) = 1;
                recordDone(task[k], rec);
              },
              images);
          failRest("the batch ended without this job's record");
        } else {
          const JobRecord rec = runJob(plan, plan.jobs[task.front()], images);
          recorded[0] = 1;
          recordDone(task.front(), rec);
        }
      } catch (const std::exception& e) {
        failRest(e.what());
      } catch (...) {
        failRest("unknown exception");
      }
    });
  }
  if (after_case)
    for (size_t k = 0; k < plan.scenes.size(); ++k)
      if (pending[k] == 0) queueAfterCase(k, false);
  queue.run(threads);
  return out;
}

std::vector<size_t> parseJobList(const std::string& list, size_t job_count) {
  // A whole non-negative number below job_count, or an error naming item.
  auto index = [&](const std::string& text, const std::string& item) {
    if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
      throw std::runtime_error("job list \"" + list + "\": item \"" + item +
                               "\": expected a job index or a range LO-HI of them");
    const size_t k = std::stoull(text);
    if (k >= job_count)
      throw std::runtime_error("job list \"" + list + "\": item \"" + item + "\": job " + text +
                               " is not in the plan (it has jobs 0 to " + std::to_string(job_count - 1) + ")");
    return k;
  };
  if (job_count == 0) throw std::runtime_error("job list \"" + list + "\": the plan has no jobs");
  std::vector<size_t> jobs;
  std::vector<bool> seen(job_count, false);
  size_t at = 0;
  while (true) {
    const size_t comma = list.find(',', at);
    const std::string item = list.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    const size_t dash = item.find('-');
    const size_t lo = index(item.substr(0, dash), item);
    const size_t hi = dash == std::string::npos ? lo : index(item.substr(dash + 1), item);
    if (hi < lo) throw std::runtime_error("job list \"" + list + "\": item \"" + item + "\": the range ends before it starts");
    for (size_t k = lo; k <= hi; ++k) {
      if (seen[k]) throw std::runtime_error("job list \"" + list + "\": job " + std::to_string(k) + " is given twice");
      seen[k] = true;
      jobs.push_back(k);
    }
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return jobs;
}

}  // namespace xval::validation
