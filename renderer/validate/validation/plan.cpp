// The plan of `xval validate` (plan.h).
#include "validate/validation/plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "validate/tolerances.h"
#include "validate/validation/file_fields.h"
#include "validate/validation/job_record.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

constexpr const char* kPlanFormat = "xval-validate-plan/1";

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

}  // namespace

std::string inputHash(const Scene& scene, const fs::path& scene_file, const std::string& renderer) {
  Fnv f;
  f.add(kRecordFormat);
  f.add(renderer);
  f.add(readBytes(scene_file));
  if (scene.material.texture && scene.material.texture->source == TextureSpec::Source::Image)
    f.add(readBytes(scene.material.texture->path));
  return f.hex();
}

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
  writeFileAtomically(planFile(plan.dir), j.dump(2) + "\n");
}

Plan readPlan(const fs::path& file) {
  const std::string name = file.string();
  // As a scene file: a duplicated key, deep nesting or a number beyond a
  // double is an error naming the field (scene/json_reader.h).
  const J j = parseOrderedJsonText(readJsonFile(file, "plan"), name);
  FieldReader rd{name};
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

}  // namespace xval::validation
