// The plan of `xval validate` (plan.h).
#include "validate/validation/plan.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <exception>
#include <map>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "geometry/model_file.h"
#include "files/sha256.h"
#include "renderers/renderer_file.h"
#include "renderers/registry.h"
#include "scene/json_reader.h"
#include "lint/scene_lint.h"
#include "scene_file/scene_set.h"
#include "validate/tolerances.h"
#include "validate/validation/file_fields.h"
#include "validate/validation/job_record.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

constexpr const char* kPlanFormat = "xval-validate-plan/2";

struct Fnv {
  uint64_t h = 1469598103934665603ull;
  void add(const std::string& bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // separator
  }
  std::string hex() const { return fmt::format("{:016x}", h); }
};

// The scene's name names its case folder OUT/<name>/: the one scene-name
// rule for a case folder (sceneNameProblem).
void checkSceneName(const std::string& name, const std::string& where) {
  const std::string problem = sceneNameProblem(name, SceneNameUse::CaseFolder);
  if (!problem.empty())
    throw std::runtime_error(where + ": name: " + nlohmann::json(name).dump(-1, ' ', false,
                                                                          nlohmann::json::error_handler_t::replace) +
                             ": cannot name a case folder: " + problem);
}

// A case folder, if it exists already, is a real folder (not a link
// planted or left there): refused before anything renders.
void checkCaseFolder(const fs::path& folder, const fs::path& scene_file) {
  const fs::file_status st = fs::symlink_status(folder);
  if (fs::is_symlink(st) || (fs::exists(st) && !fs::is_directory(st)))
    throw std::runtime_error(folder.string() + ": " + scene_file.string() + "'s case folder " +
                             (fs::is_symlink(st) ? "is a symbolic link; xval does not write through links "
                                                   "inside its output folder (remove it)"
                                                 : "exists and is not a folder"));
}

// The run's renderers the scene is not meant for (renderers::meantFor: its
// `renderers` field names neither them nor, for a golden set, the renderer
// whose images it stores).
// A restricted renderer (Renderer::restricted: a native tier) renders only
// the scenes that name it: left out of every other, with kNotNamed.
const char* const kNotNamed = "it renders only the scenes whose `renderers` field names it";

bool names(const Scene& scene, const std::string& id) {
  return std::find(scene.renderers.begin(), scene.renderers.end(), id) != scene.renderers.end();
}

std::vector<LeftOut> leftOut(const Scene& scene, const std::vector<std::string>& run, NotMeantFor mode) {
  std::vector<LeftOut> out;
  for (const std::string& r : run) {
    const renderers::Renderer& renderer = renderers::registry().at(r);
    if (mode == NotMeantFor::LeaveOut && renderer.restricted() && !names(scene, r))
      out.push_back({r, kNotNamed});
    else if (!renderers::meantFor(scene.renderers, renderer))
      out.push_back({r, "the scene is meant for " + renderers::joinNames(scene.renderers) +
                            " only (its `renderers` field)"});
  }
  return out;
}

// Adds to `run` (kept in registry order) the restricted renderers the
// scene names that it lacks.
void addNamedRestricted(const Scene& scene, std::vector<std::string>& run) {
  bool added = false;
  for (const std::string& id : scene.renderers)
    if (renderers::registry().at(id).restricted() && std::find(run.begin(), run.end(), id) == run.end()) {
      run.push_back(id);
      added = true;
    }
  if (!added) return;
  std::vector<std::string> ordered;
  for (const std::string& id : renderers::registry().ids())
    if (std::find(run.begin(), run.end(), id) != run.end()) ordered.push_back(id);
  run = ordered;
}

bool isLeftOut(const std::vector<LeftOut>& left_out, const std::string& renderer) {
  return std::any_of(left_out.begin(), left_out.end(), [&](const LeftOut& l) { return l.renderer == renderer; });
}

// The plan's "renderers": as runRenderers accepts them, in registry order.
std::vector<std::string> readRunRenderers(const FieldReader& rd, const J& j) {
  const J& v = rd.at(j, "renderers", "");
  std::vector<std::string> names;
  for (size_t i = 0; v.is_array() && i < v.size(); ++i) {
    if (!v[i].is_string())
      throw std::runtime_error(rd.file + ": renderers[" + std::to_string(i) + "]: " + v[i].dump() +
                               ": expected a string");
    names.push_back(v[i].get<std::string>());
  }
  if (!v.is_array() || names.empty())
    throw std::runtime_error(rd.file + ": renderers: " + v.dump() + ": expected a non-empty array of renderer ids");
  std::vector<std::string> ordered;
  try {
    ordered = planRenderers(names);
  } catch (const std::exception& e) {
    throw std::runtime_error(rd.file + ": renderers: " + e.what());
  }
  if (ordered != names)
    throw std::runtime_error(rd.file + ": renderers: " + v.dump() + ": expected registry order (" +
                             renderers::joinNames(ordered) + ")");
  return names;
}

// The plan's "scenes": names usable as case folders, unique; each
// left_out names a renderer of the run with a reason.
std::vector<PlannedScene> readScenes(const FieldReader& rd, const J& j, const std::vector<std::string>& run) {
  const J& v = rd.at(j, "scenes", "");
  if (!v.is_array() || v.empty())
    throw std::runtime_error(rd.file + ": scenes: expected a non-empty array");
  std::vector<PlannedScene> out;
  for (size_t k = 0; k < v.size(); ++k) {
    const std::string where = "scenes[" + std::to_string(k) + "].";
    PlannedScene ps{rd.str(v[k], "scene", where), rd.str(v[k], "file", where), rd.str(v[k], "path", where), {}};
    checkSceneName(ps.name, rd.file + ": " + where.substr(0, where.size() - 1));
    for (const PlannedScene& before : out)
      if (before.name == ps.name)
        throw std::runtime_error(rd.file + ": " + where + "scene: \"" + ps.name + "\": named twice");
    const J& left = rd.at(v[k], "left_out", where);
    if (!left.is_object())
      throw std::runtime_error(rd.file + ": " + where + "left_out: expected an object (renderer: reason)");
    for (const auto& [renderer, reason] : left.items()) {
      if (std::find(run.begin(), run.end(), renderer) == run.end() || !reason.is_string())
        throw std::runtime_error(rd.file + ": " + where + "left_out." + renderer +
                                 ": expected a reason (a string) for a renderer of `renderers`");
      ps.left_out.push_back({renderer, reason.get<std::string>()});
    }
    out.push_back(std::move(ps));
  }
  return out;
}

// The plan's "jobs": exactly those its scenes and renderers imply, in order.
std::vector<RenderJob> readJobs(const FieldReader& rd, const J& j, const Plan& plan) {
  // The jobs the scenes and renderers imply, in order: (scene, renderer).
  std::vector<std::pair<const PlannedScene*, std::string>> expected;
  for (const PlannedScene& ps : plan.scenes)
    for (const std::string& r : plan.renderers)
      if (!isLeftOut(ps.left_out, r)) expected.emplace_back(&ps, r);
  const J& jobs = rd.at(j, "jobs", "");
  std::vector<RenderJob> out;
  if (!jobs.is_array() || jobs.size() != expected.size())
    throw std::runtime_error(rd.file + ": jobs: expected an array of " + std::to_string(expected.size()) +
                             " jobs (per scene, one for each of " + renderers::joinNames(plan.renderers) +
                             " it is not left out of), got " +
                             (jobs.is_array() ? std::to_string(jobs.size()) + " entries" : jobs.type_name()));
  for (size_t k = 0; k < jobs.size(); ++k) {
    const std::string where = "jobs[" + std::to_string(k) + "].";
    const J& e = jobs[k];
    RenderJob job;
    const double index = rd.num(e, "index", where);
    if (index != double(k))
      throw std::runtime_error(rd.file + ": " + where + "index: " + e["index"].dump() + ": expected " +
                               std::to_string(k));
    job.index = k;
    const auto& [ps, renderer] = expected[k];
    job.scene = rd.str(e, "scene", where);
    job.renderer = rd.str(e, "renderer", where);
    if (job.scene != ps->name || job.renderer != renderer)
      throw std::runtime_error(rd.file + ": " + where + "scene/renderer: \"" + job.scene + "\"/\"" + job.renderer +
                               "\": expected \"" + ps->name + "\"/\"" + renderer +
                               "\" (jobs go scene by scene, in the order of `renderers`)");
    job.file = rd.str(e, "file", where);
    job.path = rd.str(e, "path", where);
    if (job.file != ps->file || job.path != ps->path)
      throw std::runtime_error(rd.file + ": " + where + "file/path: \"" + job.file + "\"/\"" + job.path.string() +
                               "\": expected the scene's, \"" + ps->file + "\"/\"" + ps->path.string() + "\"");
    job.input_hash = rd.str(e, "input_hash", where);
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"exr", job.exr()},
                                     {"png", job.png()},
                                     {"record", job.record()}}) {
      const std::string got = rd.str(e, key, where);
      if (got != value)
        throw std::runtime_error(rd.file + ": " + where + key + ": \"" + got + "\": expected \"" + value +
                                 "\" (output paths follow from the scene and renderer)");
    }
    out.push_back(job);
  }
  return out;
}

// The run's renderers defined by a file, and the maker of a golden set
// when a file defines it (Renderer::images_of).
std::vector<RendererFile> rendererFiles(const std::vector<std::string>& run) {
  std::vector<RendererFile> out;
  for (const std::string& id : run) {
    const renderers::Renderer* run_r = renderers::registry().find(id);
    for (const std::string& name : {id, run_r ? run_r->images_of : std::string()}) {
      const renderers::Renderer* r = name.empty() ? nullptr : renderers::registry().find(name);
      if (!r || r->definition_file.empty()) continue;
      if (std::none_of(out.begin(), out.end(), [&](const RendererFile& f) { return f.name == r->id; }))
        out.push_back({r->id, r->definition_file, sha256File(r->definition_file)});
    }
  }
  return out;
}

// The plan's "renderer_files" (absent: none), each checked against its
// file and added to the registry unless it is there from that file.
std::vector<RendererFile> readRendererFiles(const FieldReader& rd, const J& j) {
  std::vector<RendererFile> out;
  if (!j.contains("renderer_files")) return out;
  const J& v = j["renderer_files"];
  if (!v.is_array()) throw std::runtime_error(rd.file + ": renderer_files: expected an array");
  for (size_t k = 0; k < v.size(); ++k) {
    const std::string where = "renderer_files[" + std::to_string(k) + "].";
    RendererFile f{rd.str(v[k], "name", where), rd.str(v[k], "path", where), rd.str(v[k], "sha256", where)};
    const std::string at = rd.file + ": " + where;
    if (!f.path.is_absolute()) throw std::runtime_error(at + "path: \"" + f.path.string() + "\": expected an absolute path");
    if (!std::filesystem::is_regular_file(f.path))
      throw std::runtime_error(at + "path: " + f.path.string() + ": the renderer file of " + f.name +
                               " is missing (the plan's jobs render with it; make a new plan)");
    if (const std::string now = sha256File(f.path); now != f.sha256)
      throw std::runtime_error(at + "path: " + f.path.string() + ": the renderer file of " + f.name +
                               " changed since the plan was made (SHA-256 " + now + ", the plan's " + f.sha256 +
                               "); its jobs would render with another renderer: make a new plan");
    if (const renderers::Renderer* r = renderers::registry().find(f.name)) {
      if (r->definition_file != f.path)
        throw std::runtime_error(at + "name: \"" + f.name + "\": already a renderer " +
                                 (r->definition_file.empty() ? std::string("built into xval")
                                                             : "defined by " + r->definition_file.string()));
    } else {
      renderers::registerRendererFiles({f.path.string()});
      const renderers::Renderer* added = renderers::registry().find(f.name);
      if (!added || added->definition_file != f.path)
        throw std::runtime_error(at + "name: \"" + f.name + "\": " + f.path.string() + " defines another renderer");
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

void forEachInput(const Scene& scene, const fs::path& scene_file, const std::function<void(const std::string&)>& add) {
  add(readBytes(scene_file));
  if (scene.material.texture && scene.material.texture->source == TextureSpec::Source::Image)
    add(readBytes(scene.material.texture->path));
  // Each object's own image texture and model file with every file the
  // model file is made of (geometry/model_file.h, Model::files: an OBJ's
  // mtl and images, a glTF's buffers), each under its name.
  for (const SceneObject& o : scene.objects) {
    if (o.material && o.material->texture && o.material->texture->source == TextureSpec::Source::Image)
      add(readBytes(o.material->texture->path));
    if (const auto* m = std::get_if<MeshFile>(&o.shape))
      for (const fs::path& file : m->model->files) {
        add(file.filename().string());
        add(readBytes(file));
      }
  }
}

std::string inputHash(const Scene& scene, const fs::path& scene_file, const std::string& renderer) {
  Fnv f;
  f.add(kRecordFormat);
  f.add(renderer);
  if (const renderers::Renderer* r = renderers::registry().find(renderer); r && !r->definition_file.empty())
    f.add(readBytes(r->definition_file));
  forEachInput(scene, scene_file, [&](const std::string& bytes) { f.add(bytes); });
  return f.hex();
}

std::string exportInputsKey(const Scene& scene, const fs::path& scene_file) {
  return sha256Pieces([&](const std::function<void(const char*, size_t)>& update) {
    // Each piece with its length, so no two sequences of pieces feed the same bytes.
    auto add = [&](const std::string& bytes) {
      const std::string n = std::to_string(bytes.size()) + ":";
      update(n.data(), n.size());
      update(bytes.data(), bytes.size());
    };
    add(fs::absolute(scene_file).lexically_normal().string());
    forEachInput(scene, scene_file, add);
  });
}

std::vector<std::string> jobRenderers() { return renderers::registry().validateIds(); }

bool runsWhenNamed(const std::string& id) {
  const renderers::Renderer* r = renderers::registry().find(id);
  return r && (!r->images_of.empty() || r->restricted());
}

bool leftOutUnsaid(const LeftOut& l) { return l.reason == kNotNamed; }

std::vector<std::string> runRenderers(const std::vector<std::string>& names) {
  const std::vector<std::string> every = jobRenderers();
  if (names.empty()) return every;
  // Besides validate's renderers (the every-scene ones and the geometry
  // checks: a run leaves a check out by not naming it), the golden sets when named
  // (renderers/golden.cpp: `golden`, `golden-NAME`, also spelled golden:NAME)
  // and the restricted renderers (native tiers) when named.
  std::vector<std::string> named = names;
  for (std::string& n : named)
    if (const std::string id = renderers::goldenAlias(n); !id.empty()) n = id;
  std::vector<std::string> runnable;
  for (const std::string& id : renderers::registry().ids())
    if (std::find(every.begin(), every.end(), id) != every.end() || runsWhenNamed(id))
      runnable.push_back(id);
  for (size_t i = 0; i < named.size(); ++i) {
    if (std::find(runnable.begin(), runnable.end(), named[i]) == runnable.end())
      throw std::runtime_error("--renderers: \"" + names[i] + "\": not a renderer validate runs (expected " +
                               renderers::joinNames(every) + " or a golden set; xval renderers lists them)");
    if (std::find(named.begin(), named.begin() + i, named[i]) != named.begin() + i)
      throw std::runtime_error("--renderers: \"" + names[i] + "\" named twice");
  }
  if (names.size() < 2)
    throw std::runtime_error("--renderers: expected at least two renderers (a comparison needs two), got " +
                             renderers::joinNames(names));
  std::vector<std::string> out;
  for (const std::string& id : runnable)
    if (std::find(named.begin(), named.end(), id) != named.end()) out.push_back(id);
  return out;
}

std::vector<std::string> crosscheckRenderers(const std::string& renderer) {
  const std::string golden = renderers::goldenAlias(renderer);
  const renderers::Renderer& r = renderers::registry().at(golden.empty() ? renderer : golden);
  if (r.reference)
    throw std::runtime_error("--renderer " + renderer + ": the reference renderer is compared with itself");
  return {renderers::registry().reference().id, r.id};
}

std::vector<std::string> planRenderers(const std::vector<std::string>& names) {
  if (names.size() == 2 && names[0] == renderers::registry().reference().id) return crosscheckRenderers(names[1]);
  return runRenderers(names);
}

std::vector<size_t> sceneJobs(const Plan& plan, size_t k) {
  std::vector<size_t> out;
  for (const RenderJob& job : plan.jobs)
    if (job.scene == plan.scenes[k].name) out.push_back(job.index);
  return out;
}

fs::path planFile(const fs::path& dir) { return dir / "jobs.json"; }

void removeVerdict(const Plan& plan) {
  for (const char* f : {"results.json", "report.html"}) {
    std::error_code ec;
    if (!fs::remove(plan.dir / f, ec) && ec)
      throw std::runtime_error((plan.dir / f).string() + ": cannot remove the previous run's: " + ec.message());
  }
}

Plan makePlan(const std::vector<std::string>& inputs, const std::string& tolerances,
              const fs::path& dir, double timeout_seconds, const Budget& budget,
              const std::vector<std::string>& run_renderers, NotMeantFor not_meant_for) {
  Plan plan;
  plan.dir = fs::absolute(dir).lexically_normal();
  if (!plan.dir.has_filename()) plan.dir = plan.dir.parent_path();  // "out/" -> "out"
  checkToolPath(plan.dir);
  const std::vector<fs::path> scene_files = sceneFiles(inputs, "xval validate");  // the rule: scene_file/scene_set.h
  const ToleranceFile tol_file = findToleranceFile(tolerances, scene_files);  // the rule: tolerances.h
  plan.tolerances = tolerances.empty() ? tol_file.shown() : tolerances;
  plan.tolerances_path = tol_file.path;
  loadTolerances(plan.tolerances_path);  // fail early on a bad tolerance file
  std::fprintf(stderr, "xval validate: tolerances: %s\n", tol_file.describe().c_str());
  plan.timeout_seconds = timeout_seconds;
  plan.budget = budget;
  plan.renderers = planRenderers(run_renderers);
  // The default run takes each restricted renderer a scene names (a native
  // tier runs on its scenes); a run given its renderers takes those only.
  const bool add_named = not_meant_for == NotMeantFor::LeaveOut && plan.renderers == jobRenderers();
  std::map<std::string, std::string> seen;  // scene name -> file
  // Every invalid scene is reported, not only the first: a folder of
  // scenes is mended in one pass. Nothing renders until all are valid.
  std::vector<std::string> invalid;
  std::exception_ptr first_invalid;  // one invalid scene: its own error, as thrown
  for (const auto& f : scene_files) {
    Scene scene;
    try {
      scene = loadScene(f, plan.budget);
      checkSceneName(scene.name, f.string());
      if (not_meant_for == NotMeantFor::Refuse)
        for (const LeftOut& l : leftOut(scene, plan.renderers, not_meant_for))
          throw std::runtime_error(f.string() + ": renderers: the scene is meant for " +
                                   renderers::joinNames(scene.renderers) + " only, not " + l.renderer);
      checkCaseFolder(plan.dir / scene.name, f);
      printSceneWarnings("xval validate", scene);  // recorded by the compare step (results.json)
      auto [it, fresh] = seen.emplace(scene.name, f.string());
      if (!fresh)
        throw std::runtime_error(f.string() + ": name: \"" + scene.name + "\": also the name of " +
                                 it->second + " (scene names name the output folders: expected unique)");
    } catch (const std::exception& e) {
      invalid.push_back(e.what());
      if (!first_invalid) first_invalid = std::current_exception();
      continue;
    }
    if (add_named) addNamedRestricted(scene, plan.renderers);
    PlannedScene planned{scene.name, f.string(), fs::absolute(f).lexically_normal(),
                         leftOut(scene, plan.renderers, not_meant_for)};
    for (const LeftOut& l : planned.left_out)
      if (!leftOutUnsaid(l))
        std::fprintf(stderr, "xval validate: %s: %s left out: %s\n", scene.name.c_str(), l.renderer.c_str(),
                     l.reason.c_str());
    for (const std::string& r : plan.renderers) {
      if (isLeftOut(planned.left_out, r)) continue;
      RenderJob job;
      job.index = plan.jobs.size();
      job.scene = scene.name;
      job.file = f.string();
      job.path = fs::absolute(f).lexically_normal();
      job.renderer = r;
      job.input_hash = inputHash(scene, job.path, r);
      plan.jobs.push_back(job);
    }
    plan.scenes.push_back(std::move(planned));
  }
  if (invalid.size() == 1) std::rethrow_exception(first_invalid);
  if (!invalid.empty()) {
    std::string all = std::to_string(invalid.size()) + " of " + std::to_string(scene_files.size()) +
                      " scenes are invalid (nothing rendered):";
    for (const std::string& why : invalid) all += "\n  " + why;
    throw std::runtime_error(all);
  }
  // A restricted renderer a later scene added to the run: left out of the
  // scenes planned before it that do not name it.
  std::set<std::pair<std::string, std::string>> jobs;  // (scene, renderer)
  for (const RenderJob& j : plan.jobs) jobs.emplace(j.scene, j.renderer);
  for (PlannedScene& ps : plan.scenes)
    for (const std::string& r : plan.renderers)
      if (renderers::registry().at(r).restricted() && !isLeftOut(ps.left_out, r) && !jobs.count({ps.name, r}))
        ps.left_out.push_back({r, kNotNamed});
  plan.renderer_files = rendererFiles(plan.renderers);
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
  j["renderers"] = plan.renderers;
  j["renderer_files"] = J::array();
  for (const RendererFile& f : plan.renderer_files)
    j["renderer_files"].push_back({{"name", f.name}, {"path", f.path.string()}, {"sha256", f.sha256}});
  j["scenes"] = J::array();
  for (const PlannedScene& s : plan.scenes) {
    J left = J::object();
    for (const LeftOut& l : s.left_out) left[l.renderer] = l.reason;
    j["scenes"].push_back({{"scene", s.name}, {"file", s.file}, {"path", s.path.string()}, {"left_out", left}});
  }
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
  plan.renderer_files = readRendererFiles(rd, j);
  plan.renderers = readRunRenderers(rd, j);
  plan.scenes = readScenes(rd, j, plan.renderers);
  plan.jobs = readJobs(rd, j, plan);
  return plan;
}

}  // namespace xval::validation
