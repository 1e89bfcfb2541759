// The jobs of `xval validate`: plan, run one job, compare (validation_jobs.h).
#include "validate/validation_jobs.h"
#include "process/job_pool.h"
#include "validate/common/provenance.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>
#include <OpenImageIO/oiioversion.h>

#include "process/run_process.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/compare.h"
#include "image/image.h"
#include "image/perceptual.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "scene/scene_loader.h"
#include "validate/colour_stats.h"
#include "validate/paper_claims.h"
#include "validate/report.h"
#include "validate/tolerances.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

constexpr const char* kPlanFormat = "xval-validate-plan/1";
constexpr const char* kRecordFormat = "xval-validate-job/1";
constexpr int kPreviewSide = 360;  // report images: 8-bit, at most 360 px

double nowUnix() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

struct Fnv {
  uint64_t h = 1469598103934665603ull;
  void add(const std::string& bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // separator
  }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

// What a render depends on: the renderer, the scene file's bytes and, for an
// image texture, the image's bytes.
std::string inputHash(const Scene& scene, const fs::path& scene_file, const std::string& renderer) {
  Fnv f;
  f.add(kRecordFormat);
  f.add(renderer);
  f.add(readBytes(scene_file));
  if (scene.material.texture && scene.material.texture->source == TextureSpec::Source::Image)
    f.add(readBytes(scene.material.texture->path));
  // Each object's own image texture and model file (not the files a model
  // file refers to: an OBJ's mtl and images, a glTF's buffers).
  for (const SceneObject& o : scene.objects) {
    if (o.material && o.material->texture && o.material->texture->source == TextureSpec::Source::Image)
      f.add(readBytes(o.material->texture->path));
    if (const auto* m = std::get_if<MeshFile>(&o.shape)) f.add(readBytes(m->path));
  }
  return f.hex();
}

// FNV-1a over the bytes of the files that define the run's settings
// (results.json provenance.settings_hash; unchanged from the single-process
// validate so published hashes stay comparable).
std::string settingsHash(const std::vector<fs::path>& files) {
  uint64_t h = 1469598103934665603ull;
  for (const auto& f : files) {
    std::string bytes = readBytes(f);
    bytes += f.filename().string();
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

void writeAtomically(const fs::path& file, const std::string& text) { writeFileAtomically(file, text); }

std::vector<fs::path> collectScenes(const std::vector<std::string>& inputs) {
  std::vector<fs::path> out;
  for (const auto& in : inputs) {
    fs::path p(in);
    if (fs::is_directory(p)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(p))
        if (e.path().extension() == ".json") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      out.insert(out.end(), files.begin(), files.end());
    } else if (fs::is_regular_file(p)) {
      out.push_back(p);
    } else {
      throw std::runtime_error(in + ": no such scene file or folder");
    }
  }
  if (out.empty()) throw std::runtime_error("no scene files found");
  return out;
}

// The scene's name names its case folder OUT/<name>/: the one scene-name
// rule for a case folder (sceneNameProblem).
void checkSceneName(const std::string& name, const std::string& where) {
  const std::string problem = sceneNameProblem(name, SceneNameUse::CaseFolder);
  if (!problem.empty())
    throw std::runtime_error(where + ": name: " + nlohmann::json(name).dump(-1, ' ', false,
                                                                          nlohmann::json::error_handler_t::replace) +
                             ": cannot name a case folder: " + problem);
}

std::string hostName() {
  char buf[256] = {0};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// Field readers for the plan and records: errors name the file and field.
struct Reader {
  const std::string file;
  const J& at(const J& obj, const std::string& key, const std::string& where) const {
    if (!obj.is_object() || !obj.contains(key))
      throw std::runtime_error(file + ": " + where + key + ": missing");
    return obj[key];
  }
  std::string str(const J& obj, const std::string& key, const std::string& where = "") const {
    const J& v = at(obj, key, where);
    if (!v.is_string())
      throw std::runtime_error(file + ": " + where + key + ": " + v.dump() + ": expected a string");
    return v.get<std::string>();
  }
  double num(const J& obj, const std::string& key, const std::string& where = "") const {
    const J& v = at(obj, key, where);
    if (!v.is_number())
      throw std::runtime_error(file + ": " + where + key + ": " + v.dump() + ": expected a number");
    return v.get<double>();
  }
};

}  // namespace

std::vector<std::string> jobRenderers() { return renderers::registry().everySceneIds(); }

fs::path planFile(const fs::path& dir) { return dir / "jobs.json"; }

void removeVerdict(const Plan& plan) {
  for (const char* f : {"results.json", "report.html"}) {
    std::error_code ec;
    if (!fs::remove(plan.dir / f, ec) && ec)
      throw std::runtime_error((plan.dir / f).string() + ": cannot remove the previous run's: " + ec.message());
  }
}

Plan makePlan(const std::vector<std::string>& inputs, const std::string& tolerances,
              const fs::path& dir, double timeout_seconds, const Budget& budget) {
  Plan plan;
  plan.dir = fs::absolute(dir).lexically_normal();
  if (!plan.dir.has_filename()) plan.dir = plan.dir.parent_path();  // "out/" -> "out"
  checkToolPath(plan.dir);
  const std::vector<fs::path> scene_files = collectScenes(inputs);
  const ToleranceFile tol_file = findToleranceFile(tolerances, scene_files);  // the rule: tolerances.h
  plan.tolerances = tolerances.empty() ? tol_file.shown() : tolerances;
  plan.tolerances_path = tol_file.path;
  loadTolerances(plan.tolerances_path);  // fail early on a bad tolerance file
  std::fprintf(stderr, "xval validate: tolerances: %s\n", tol_file.describe().c_str());
  plan.timeout_seconds = timeout_seconds;
  plan.budget = budget;
  std::map<std::string, std::string> seen;  // scene name -> file
  for (const auto& f : scene_files) {
    Scene scene = loadScene(f, plan.budget);
    checkSceneName(scene.name, f.string());
    // Its case folder, if it exists already, is a real folder (not a link
    // planted or left there): refused before anything renders.
    const fs::file_status st = fs::symlink_status(plan.dir / scene.name);
    if (fs::is_symlink(st) || (fs::exists(st) && !fs::is_directory(st)))
      throw std::runtime_error((plan.dir / scene.name).string() + ": " + f.string() + "'s case folder " +
                               (fs::is_symlink(st) ? "is a symbolic link; xval does not write through links "
                                                     "inside its output folder (remove it)"
                                                   : "exists and is not a folder"));
    auto [it, fresh] = seen.emplace(scene.name, f.string());
    if (!fresh)
      throw std::runtime_error(f.string() + ": name: \"" + scene.name + "\": also the name of " +
                               it->second + " (scene names name the output folders: expected unique)");
    for (const std::string& r : jobRenderers()) {
      RenderJob job;
      job.index = plan.jobs.size();
      job.scene = scene.name;
      job.file = f.string();
      job.path = fs::absolute(f).lexically_normal();
      job.renderer = r;
      job.input_hash = inputHash(scene, job.path, r);
      plan.jobs.push_back(job);
    }
  }
  plan.created_unix = nowUnix();
  return plan;
}

void writePlan(const Plan& plan) {
  J j;
  j["format"] = kPlanFormat;
  j["about"] = "xval validate's render jobs: run job K with `xval validate --plan THIS_FILE --run-job K`, "
               "compare and report with `xval validate --plan THIS_FILE --compare-only`; outputs are "
               "relative to this file's folder";
  j["created_unix"] = plan.created_unix;
  j["tolerances"] = plan.tolerances;
  j["tolerances_path"] = plan.tolerances_path.string();
  j["timeout_seconds"] = plan.timeout_seconds;
  j["budget"] = {{"max_triangles", plan.budget.max_triangles},
                 {"max_samples", plan.budget.max_samples},
                 {"max_memory_mb", plan.budget.max_memory_mb}};
  j["jobs"] = J::array();
  for (const auto& job : plan.jobs)
    j["jobs"].push_back({{"index", job.index},
                         {"scene", job.scene},
                         {"renderer", job.renderer},
                         {"file", job.file},
                         {"path", job.path.string()},
                         {"input_hash", job.input_hash},
                         {"exr", job.exr()},
                         {"png", job.png()},
                         {"record", job.record()}});
  fs::create_directories(plan.dir);
  writeAtomically(planFile(plan.dir), j.dump(2) + "\n");
}

Plan readPlan(const fs::path& file) {
  const std::string name = file.string();
  // As a scene file: a duplicated key, deep nesting or a number beyond a
  // double is an error naming the field (scene/json_reader.h).
  const J j = parseOrderedJsonText(readJsonFile(file, "plan"), name);
  Reader rd{name};
  const std::string format = rd.str(j, "format");
  if (format != kPlanFormat)
    throw std::runtime_error(name + ": format: \"" + format + "\": expected \"" + kPlanFormat + "\"");
  Plan plan;
  plan.dir = fs::absolute(file).lexically_normal().parent_path();
  checkToolPath(plan.dir);
  plan.created_unix = rd.num(j, "created_unix");
  plan.tolerances = rd.str(j, "tolerances");
  plan.tolerances_path = rd.str(j, "tolerances_path");
  plan.timeout_seconds = rd.num(j, "timeout_seconds");
  if (!(plan.timeout_seconds > 0) || !std::isfinite(plan.timeout_seconds))
    throw std::runtime_error(name + ": timeout_seconds: " + j["timeout_seconds"].dump() +
                             ": expected a positive, finite number");
  // The budget every scene of the plan is loaded with (validate's
  // --max-triangles, --max-samples, --max-memory-mb, --allow-large); a plan
  // without one uses the defaults.
  if (j.contains("budget")) {
    const J& b = j["budget"];
    if (!b.is_object())
      throw std::runtime_error(name + ": budget: expected an object, got " + std::string(b.type_name()));
    for (auto [key, field] : {std::pair{"max_triangles", &plan.budget.max_triangles},
                              std::pair{"max_samples", &plan.budget.max_samples},
                              std::pair{"max_memory_mb", &plan.budget.max_memory_mb}}) {
      const J& v = rd.at(b, key, "budget.");
      if (!v.is_number_integer() || v.get<long long>() <= 0)
        throw std::runtime_error(name + ": budget." + key + ": " + v.dump() + ": expected a positive integer");
      *field = v.get<long long>();
    }
  }
  const J& jobs = rd.at(j, "jobs", "");
  const std::vector<std::string> per_scene = jobRenderers();
  const size_t n = per_scene.size();
  if (!jobs.is_array() || jobs.empty() || jobs.size() % n != 0)
    throw std::runtime_error(name + ": jobs: expected a non-empty array of " + std::to_string(n) +
                             " jobs per scene (" + renderers::joinNames(per_scene) + "), got " +
                             (jobs.is_array() ? std::to_string(jobs.size()) + " entries" : jobs.type_name()));
  for (size_t k = 0; k < jobs.size(); ++k) {
    const std::string where = "jobs[" + std::to_string(k) + "].";
    const J& e = jobs[k];
    RenderJob job;
    const double index = rd.num(e, "index", where);
    if (index != double(k))
      throw std::runtime_error(name + ": " + where + "index: " + e["index"].dump() + ": expected " +
                               std::to_string(k));
    job.index = k;
    job.scene = rd.str(e, "scene", where);
    checkSceneName(job.scene, name + ": " + where.substr(0, where.size() - 1));
    job.renderer = rd.str(e, "renderer", where);
    const std::string& expect = per_scene[k % n];
    if (job.renderer != expect)
      throw std::runtime_error(name + ": " + where + "renderer: \"" + job.renderer + "\": expected \"" +
                               expect + "\" (jobs go " + renderers::joinNames(per_scene) + " per scene)");
    if (k % n != 0 && job.scene != plan.jobs[k - k % n].scene)
      throw std::runtime_error(name + ": " + where + "scene: \"" + job.scene + "\": expected \"" +
                               plan.jobs[k - k % n].scene + "\" (the jobs of a scene are adjacent)");
    job.file = rd.str(e, "file", where);
    job.path = rd.str(e, "path", where);
    job.input_hash = rd.str(e, "input_hash", where);
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"exr", job.exr()},
                                     {"png", job.png()},
                                     {"record", job.record()}}) {
      const std::string got = rd.str(e, key, where);
      if (got != value)
        throw std::runtime_error(name + ": " + where + key + ": \"" + got + "\": expected \"" + value +
                                 "\" (output paths follow from the scene and renderer)");
    }
    plan.jobs.push_back(job);
  }
  return plan;
}

JobRecord readRecord(const Plan& plan, const RenderJob& job) {
  JobRecord rec;
  const fs::path file = plan.dir / job.record();
  if (!fs::exists(file)) {
    rec.problem = file.string() + ": no record (the job has not run, or was interrupted)";
    return rec;
  }
  try {
    const J j = parseOrderedJsonText(readJsonFile(file, "job record"), file.string());
    Reader rd{file.string()};
    const std::string format = rd.str(j, "format");
    if (format != kRecordFormat)
      throw std::runtime_error(file.string() + ": format: \"" + format + "\": expected \"" + kRecordFormat + "\"");
    const std::string scene = rd.str(j, "scene"), renderer = rd.str(j, "renderer");
    if (scene != job.scene || renderer != job.renderer)
      throw std::runtime_error(file.string() + ": scene/renderer: \"" + scene + "\"/\"" + renderer +
                               "\": expected \"" + job.scene + "\"/\"" + job.renderer + "\"");
    rec.input_hash = rd.str(j, "input_hash");
    rec.seconds = rd.num(j, "seconds");
    if (j.contains("render_seconds")) rec.render_seconds = rd.num(j, "render_seconds");
    if (j.contains("error")) rec.error = rd.str(j, "error");
    rec.present = true;
  } catch (const std::exception& e) {
    rec.problem = e.what();
  }
  return rec;
}

bool isDone(const Plan& plan, const RenderJob& job, std::string* why) {
  auto no = [why](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  JobRecord rec = readRecord(plan, job);
  if (!rec.present) return no(rec.problem);
  if (!rec.error.empty()) return no("the last render failed: " + rec.error);
  if (rec.input_hash != job.input_hash)
    return no((plan.dir / job.record()).string() + ": rendered from other inputs (input_hash " +
              rec.input_hash + ", the plan's is " + job.input_hash + ")");
  for (const std::string& f : {job.exr(), job.png()})
    if (!fs::exists(plan.dir / f)) return no((plan.dir / f).string() + ": missing");
  return true;
}

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
      request.work_dir = cdir / (job.renderer + ".work");
      makeFreshFolder(request.work_dir);
    }
    renderers::RenderInfo info;
    Image image = renderer.render(scene, request, &info);
    rec.render_seconds = info.render_seconds;
    writeImage(image, plan.dir / job.exr());
    writePreviewPng(image, plan.dir / job.png(), kPreviewSide);
  } catch (const std::exception& e) {
    rec.error = e.what();
  }
  rec.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  J j;
  j["format"] = kRecordFormat;
  j["job"] = job.index;
  j["scene"] = job.scene;
  j["renderer"] = job.renderer;
  j["input_hash"] = job.input_hash;
  j["seconds"] = rec.seconds;
  if (rec.render_seconds >= 0) j["render_seconds"] = rec.render_seconds;
  if (!rec.error.empty()) j["error"] = rec.error;
  j["host"] = hostName();
  j["finished_unix"] = nowUnix();
  try {
    writeAtomically(record, j.dump(2) + "\n");
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
                 rec.error.empty() ? "ok   " : "ERROR", rec.seconds, el,
                 el * double(todo.size() - n) / double(n));
    if (!rec.error.empty()) std::fprintf(stderr, "  %s\n", rec.error.c_str());
  });
}

int compareAndReport(const Plan& plan, const ReportSections& sections) {
  const fs::path& dir = plan.dir;
  const J jsections = sectionsJson(sections, dir);  // fails early on a folder with no results
  // The old verdict must not outlive this run: whatever stops it from here
  // on (an error, a kill) leaves no results.json or report.html at all.
  removeVerdict(plan);
  ToleranceTable table = loadTolerances(plan.tolerances_path);
  bool any_error = false, any_fail = false;
  J jcases = J::array();
  std::vector<fs::path> setting_files{plan.tolerances_path};
  const std::vector<const renderers::Renderer*> rs = renderers::registry().everySceneRenderers();
  const std::vector<renderers::RendererPair> pairs = renderers::unorderedPairs(rs.size());
  const std::string& reference_id = renderers::registry().reference().id;
  for (size_t first = 0; first < plan.jobs.size(); first += rs.size()) {
    const RenderJob& j0 = plan.jobs[first];
    Scene scene = loadScene(j0.path, plan.budget);
    if (scene.name != j0.scene)
      throw std::runtime_error(j0.path.string() + ": name: \"" + scene.name + "\": the plan (" +
                               planFile(dir).string() + ") says \"" + j0.scene + "\": plan again");
    setting_files.push_back(j0.path);
    makeRealFolder(dir, dir / j0.scene);  // the diff images go there: never through a link
    J jc;
    jc["scene"] = j0.scene;
    jc["file"] = j0.file;
    struct Render {
      JobRecord rec;
      Image image;
      std::string error;
    };
    std::map<std::string, Render> renders;
    for (size_t r = 0; r < rs.size(); ++r) {
      const RenderJob& job = plan.jobs[first + r];
      Render& rr = renders[job.renderer];
      rr.rec = readRecord(plan, job);
      if (!rr.rec.present) {
        rr.error = "not rendered: " + rr.rec.problem;
      } else if (!rr.rec.error.empty()) {
        rr.error = rr.rec.error;
      } else if (rr.rec.input_hash != job.input_hash) {
        rr.error = (dir / job.record()).string() + ": rendered from other inputs (input_hash " +
                   rr.rec.input_hash + ", the plan's is " + job.input_hash + "): run the job again";
      } else {
        try {
          rr.image = readImage(dir / job.exr());
        } catch (const std::exception& e) {
          rr.error = std::string("the record says ok but the image cannot be read: ") + e.what();
        }
      }
      J jr = {{"seconds", rr.rec.seconds}, {"image", job.png()}};
      if (rr.rec.render_seconds >= 0) jr["render_seconds"] = rr.rec.render_seconds;
      if (!rr.error.empty()) jr["error"] = rr.error, any_error = true;
      jc["renders"][job.renderer] = jr;
    }
    std::vector<int> verdict(pairs.size());
    J jpairs = J::array();
    for (size_t p = 0; p < pairs.size(); ++p) {
      const renderers::Renderer& ra = *rs[pairs[p].a];
      const renderers::Renderer& rb = *rs[pairs[p].b];
      Render& A = renders[ra.id];
      Render& B = renders[rb.id];
      const std::string key = renderers::pairKey(ra, rb);
      J jp = {{"pair", key}};
      if (!A.error.empty() || !B.error.empty()) {
        verdict[p] = -1;
        jp["error"] = "not compared: a render failed";
        jpairs.push_back(jp);
        continue;
      }
      std::string reason;
      const Tolerance tol = table.lookupPair(scene, ra.id, rb.id, &reason);
      if (!ra.reference && !rb.reference) {
        // The reference's diagnostics describe the same pixels.
        A.image.depth = renders[reference_id].image.depth;
        A.image.backfacing = renders[reference_id].image.backfacing;
        A.image.incidence = renders[reference_id].image.incidence;
      }
      CompareMetrics m = compareImages(A.image, B.image, tol);
      PerceptualMetrics pm = perceptualMetrics(A.image, B.image);
      const Image diff = differenceImage(A.image, B.image);
      writeImage(diff, dir / j0.scene / ("diff_" + key + ".exr"));
      jp["heat_map"] = writeHeatMapPng(diff, dir, j0.scene, key);  // the report only shows it
      J jm = J::parse(toJson(m, tol, &pm));
      jm["tolerance_reason"] = reason;
      jp["metrics"] = jm;
      jp["pass"] = tol.passes(m);
      // Known differences are the classified ones and a declared reason.
      jp["classification"] = {
          {"known", m.over_occlusion_edge + m.over_backfacing + m.over_grazing},
          {"unexplained", m.over_unexplained},
          {"declared", !reason.empty()}};
      verdict[p] = tol.passes(m) ? 1 : 0;
      any_fail |= !tol.passes(m);
      jpairs.push_back(jp);
    }
    jc["pairs"] = jpairs;
    if (renders[reference_id].error.empty()) {
      ColourStats st = colourStats(renders[reference_id].image);
      jc["colour_stats"] = {{"lit_pixels", st.lit_pixels},
                            {"mean_chroma", st.mean_chroma},
                            {"mean_albedo_chroma", st.mean_albedo_chroma},
                            {"grey_fraction", st.grey_fraction},
                            {"hue_error_deg", st.hue_error_deg}};
    }
    jc["attribution"] = renderers::attribute(rs, verdict);
    jc["pass"] = std::all_of(verdict.begin(), verdict.end(), [](int v) { return v == 1; });
    jcases.push_back(jc);
  }
  J results;
  results["format"] = "xval-results/1";
  // The outside tools' versions (probed with a time-out, renderers/registry.h).
  results["provenance"] = J::object();
  for (const renderers::Renderer* r : rs)
    if (r->external()) results["provenance"][r->id] = renderers::registry().version(r->id);
  // The one provenance record (validate/common/provenance.h): the compiler
  // that built this xval, the commit (with -dirty) it ran in.
  const Provenance prov = collectProvenance(plan.dir / "version.log");
  results["provenance"]["openimageio"] = prov.openimageio;
  results["provenance"]["compiler"] = prov.compiler;
  results["provenance"]["tolerances"] = plan.tolerances;
  results["provenance"]["git_commit"] = prov.git_commit;
  results["provenance"]["settings_hash"] = settingsHash(setting_files);
  // From the plan's making to now: on a cluster this includes the time the
  // jobs waited in the queue.
  results["wall_seconds"] = std::max(0.0, nowUnix() - plan.created_unix);
  results["cases"] = jcases;
  if (J claims = paperClaims(jcases); !claims.is_null()) results["paper_claims"] = claims;
  if (!jsections.empty()) results["sections"] = jsections;
  writeAtomically(dir / "results.json", results.dump(2) + "\n");
  writeReport(dir / "results.json", dir / "report.html");
  // For every failing case: how to look closer, and how to accept it. The
  // paths are single-quoted for a POSIX shell (' becomes '\''), so a
  // pasted command cannot run anything a scene or folder name contains.
  auto shellQuote = [](const std::string& v) {
    std::string q = "'";
    for (char c : v) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  for (const auto& jc : jcases) {
    if (jc["pass"].get<bool>()) continue;
    std::fprintf(stderr, "FAIL %s (%s)\n", jc["scene"].get<std::string>().c_str(),
                 jc["attribution"].get<std::string>().c_str());
    for (const renderers::Renderer* r : rs)
      if (!r->reference)
        std::fprintf(stderr, "  look closer: xval crosscheck %s --renderer %s -o %s\n",
                     shellQuote(jc["file"].get<std::string>()).c_str(), r->id.c_str(),
                     shellQuote((dir / (jc["scene"].get<std::string>() + "." + r->id)).string()).c_str());
    std::fprintf(stderr,
                 "  accept a documented difference: declare it, with its measured reason, in the\n"
                 "  `tolerances` field of %s (defaults: %s)\n"
                 "  (no golden images are kept: the reference renderer renders every run)\n",
                 jc["file"].get<std::string>().c_str(), plan.tolerances.c_str());
  }
  std::fprintf(stderr, "xval validate: %zu scenes, %s; wrote %s\n", jcases.size(),
               any_error ? "ERRORS" : any_fail ? "some cases FAIL" : "all pass",
               (dir / "report.html").c_str());
  return any_error ? 2 : any_fail ? 1 : 0;
}

}  // namespace xval::validation
