// The compare step of `xval validate` (compare_step.h).
#include "validate/validation/compare_step.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <mutex>
#include <optional>
#include <set>
#include <cstdio>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/compare.h"
#include "image/heat_map.h"
#include "image/metric_criteria.h"
#include "image/metric_table.h"
#include "image/image.h"
#include "image/pair_failure.h"
#include "image/perceptual.h"
#include "process/job_pool.h"
#include "renderers/registry.h"
#include "lint/scene_lint.h"
#include "scene_file/scene_loader.h"
#include "validate/colour_stats.h"
#include "validate/compare_outputs.h"
#include "validate/pixel_crops.h"
#include "validate/tolerances.h"
#include "render/geometry_passes.h"
#include "validate/geometry_check.h"
#include "validate/results/results.h"
#include "validate/results/case_verdict.h"
#include "validate/results/geometry_checks.h"
#include "validate/validation/job_record.h"
#include "validate/validation/next_steps.h"
#include "validate/validation/results_file.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

// One renderer's render of a case: its image, or why there is none.
struct Render {
  fs::path file;  // the EXR the image was read from
  JobRecord rec;
  Image image;
  std::string error;
  std::optional<MeasuredImage> measured;  // of image, once its first pair needs it
  const MeasuredImage& measuredOnce() {
    if (!measured) measured = measuredImage(image);
    return *measured;
  }
};
using Renders = std::map<std::string, Render>;  // by renderer id

// What every case is compared with.
struct CompareContext {
  const Plan& plan;
  const ToleranceTable table;
  ImageHandoff* images = nullptr;  // the renders this run's jobs left (image_handoff.h), or null
};

// The job's render: its record checked against the plan, then its EXR
// (none when the renderer declared the scene not expressible).
Render loadRender(const Plan& plan, const RenderJob& job, ImageHandoff* images) {
  Render r;
  r.file = plan.dir / job.exr();
  r.rec = readRecord(plan, job);
  if (!r.rec.present) {
    r.error = "not rendered: " + r.rec.problem;
  } else if (!r.rec.error.empty()) {
    r.error = r.rec.error;
  } else if (r.rec.input_hash != job.input_hash) {
    r.error = (plan.dir / job.record()).string() + ": rendered from other inputs (input_hash " +
              r.rec.input_hash + ", the plan's is " + job.input_hash + "): run the job again";
  } else if (r.rec.not_expressible.empty()) {
    try {
      std::optional<Image> kept = images ? images->take(plan.dir / job.exr()) : std::nullopt;
      r.image = kept ? std::move(*kept) : readImage(plan.dir / job.exr());
    } catch (const std::exception& e) {
      r.error = std::string("the record says ok but the image cannot be read: ") + e.what();
    }
  }
  return r;
}

bool notExpressible(const Render& r) { return r.error.empty() && !r.rec.not_expressible.empty(); }

// results.json's cases[].renders.<id>.
J renderJson(const RenderJob& job, const Render& r) {
  J jr = {{"seconds", r.rec.seconds}};
  if (notExpressible(r)) jr["not_expressible"] = r.rec.not_expressible;
  else jr["image"] = job.png();
  if (r.rec.render_seconds >= 0) jr["render_seconds"] = r.rec.render_seconds;
  if (r.rec.process_seconds >= 0) jr["process_seconds"] = r.rec.process_seconds;
  if (r.rec.parse_seconds >= 0) jr["parse_seconds"] = r.rec.parse_seconds;
  if (!r.error.empty()) jr["error"] = r.error;
  return jr;
}

// Pair verdicts (renderers::attribute's, registry.h: pass, fail, and a
// failure of the fraction within tolerance alone; -1 not compared for a
// failed render; and -2 for a pair that one of its renderers cannot
// express: not compared, and no error). -3: both renders are there but
// cannot be compared (images of different sizes: one was replaced after
// its record said ok), an error of the case that compareCase passes on to
// renderers::attribute as not compared. -4: a finding (outside the
// tolerance, as the scene declares: results.h PairVerdict::Finding), which
// renderers::attribute takes as not compared.
constexpr int kPass = renderers::kPairPasses, kFail = renderers::kPairFails,
              kFailOnlyFraction = renderers::kPairFailsOnlyOnFraction, kRenderError = -1, kNotExpressible = -2,
              kCompareError = -3, kFinding = -4;

// The pair's verdict results.json stores (results/results.h), once.
results::PairVerdict pairVerdict(int verdict) {
  switch (verdict) {
    case kPass: return results::PairVerdict::Pass;
    case kFail:
    case kFailOnlyFraction: return results::PairVerdict::Fail;
    case kNotExpressible: return results::PairVerdict::NotExpressible;
    case kFinding: return results::PairVerdict::Finding;
    default: return results::PairVerdict::Error;  // kRenderError, kCompareError
  }
}

std::vector<PairFailure> comparedPair(const CompareContext& cx, const Scene& scene, const std::string& key,
                                      const Tolerance& tol, const PairPrecision& precision, const std::string& reason,
                                      Render& A, Render& B, Renders& renders, J& jp);

// One pair of one case: compared with its tolerance, its difference EXR
// and heat map written.
J comparePair(const CompareContext& cx, const Scene& scene, const renderers::Renderer& ra,
              const renderers::Renderer& rb, Renders& renders, int& verdict) {
  Render& A = renders[ra.id];
  Render& B = renders[rb.id];
  const std::string key = renderers::pairKey(ra, rb);
  J jp = {{"pair", key}};
  if (!A.error.empty() || !B.error.empty()) {
    verdict = kRenderError;
    jp["error"] = "not compared: a render failed";
    return jp;
  }
  if (notExpressible(A) || notExpressible(B)) {
    verdict = kNotExpressible;
    std::string why;
    for (const auto* r : {&ra, &rb})
      if (notExpressible(renders[r->id])) why += (why.empty() ? "" : "; ") + r->id + ": " + renders[r->id].rec.not_expressible;
    jp["not_expressible"] = why;
    return jp;
  }
  std::string reason;
  const Tolerance tol = cx.table.lookupPair(scene, ra.id, rb.id, &reason);
  // The comparison classifies pixels by the diagnostics of its first image.
  // Without the reference in the pair, they come from the reference's render
  // when the run has one, else from B when only B carries them (a golden
  // image, which follows the external renderers in registry order): they
  // describe the same pixels. A run with the reference renderer's golden
  // images in its place takes theirs (they carry its diagnostics).
  const std::string& reference_id = renderers::registry().reference().id;
  auto ref = renders.find(reference_id);
  if (ref == renders.end())
    ref = std::find_if(renders.begin(), renders.end(), [&](const auto& entry) {
      const renderers::Renderer* r = renderers::registry().find(entry.first);
      return r && r->images_of == reference_id;
    });
  const Image* diagnostics = ref != renders.end()                         ? &ref->second.image
                             : A.image.depth.empty() && !B.image.depth.empty() ? &B.image
                                                                           : nullptr;
  if (!ra.reference && !rb.reference && diagnostics != nullptr && diagnostics != &A.image) {
    copyDiagnostics(*diagnostics, A.image);
  }
  std::vector<PairFailure> failed;
  try {
    const PairPrecision precision{renderers::precisionOf(ra), renderers::precisionOf(rb)};
    failed = comparedPair(cx, scene, key, tol, precision, reason, A, B, renders, jp);
  } catch (const std::exception& e) {
    // This pair's error, naming its files: the other pairs and cases are
    // still compared and reported.
    verdict = kCompareError;
    jp = {{"pair", key},
          {"error", "not compared: " + A.file.string() + " (" + std::to_string(A.image.width) + "x" +
                        std::to_string(A.image.height) + ") and " + B.file.string() + " (" +
                        std::to_string(B.image.width) + "x" + std::to_string(B.image.height) + "): " + e.what()}};
    return jp;
  }
  verdict = failed.empty() ? kPass : failsOnlyOnFraction(failed) ? kFailOnlyFraction : kFail;
  // A finding of one renderer of the pair (Scene::findings): the pair is
  // expected outside its tolerance. Declared by both, nothing is expected.
  const std::string* finding_a = findingOf(scene, ra.id);
  const std::string* finding_b = findingOf(scene, rb.id);
  if ((finding_a != nullptr) != (finding_b != nullptr)) {
    const std::string& id = finding_a ? ra.id : rb.id;
    jp["finding"] = {{"renderer", id}, {"why", finding_a ? *finding_a : *finding_b}};
    verdict = failed.empty() ? kFail : kFinding;
  }
  return jp;
}

// A pair whose two renders are there: its metrics, difference EXR, heat map
// and crops into jp; returns the criteria it fails (none: it passes).
// Throws when the images cannot be compared.
std::vector<PairFailure> comparedPair(const CompareContext& cx, const Scene& scene, const std::string& key,
                                      const Tolerance& tol, const PairPrecision& precision, const std::string& reason,
                                      Render& A, Render& B, Renders& renders, J& jp) {
  const PairMeasures measures =
      measurePair(A.image, B.image, tol, precision, &A.measuredOnce(), &B.measuredOnce());
  const CompareMetrics& m = measures.compare;
  const Image diff = differenceImage(A.image, B.image);
  writeImage(diff, cx.plan.dir / scene.name / diffExrName(key), kDifferenceExrCompression);
  // The heat map: the report shows it, not the EXR.
  jp["heat_map"] = writeHeatMapPng(diff, cx.plan.dir, scene.name + "/" + heatMapName(key));
  // The pair's precision bound on the same scale, beside it.
  if (const Image bound = precisionBoundImage(A.image, B.image, precision); bound.width > 0)
    jp["bound_map"] = writeHeatMapPng(bound, cx.plan.dir, scene.name + "/" + boundMapName(key), kBoundMapSide);
  std::map<std::string, const Image*> images;
  // The renders of the scene (a geometry check's passes are no render of it).
  for (const auto& [id, rr] : renders)
    if (!renderers::registry().at(id).geometry_passes)
      images[id] = rr.error.empty() && !notExpressible(rr) ? &rr.image : nullptr;
  jp["crops"] = writePairCrops(A.image, B.image, images, heatMap(diff), m, cx.plan.dir, scene.name, key);
  J jm = pairJson(measures, tol);
  jm["tolerance_reason"] = reason;
  jm["precision"] = {{"a", precisionJson(precision.a)}, {"b", precisionJson(precision.b)}};
  jp["metrics"] = jm;
  jp["pass"] = passes(measures, tol);
  std::vector<PairFailure> failed = failedCriteria(measures, tol);
  jp["failed"] = failedJson(failed);
  // Known differences are the classified ones and a declared reason.
  jp["classification"] = {{"known", m.over_tolerance - m.over_unexplained()},
                          {"unexplained", m.over_unexplained()},
                          {"declared", !reason.empty()}};
  return failed;
}

// The reference image's colour statistics (validate/colour_stats.h).
J colourStatsJson(const Image& reference) {
  const ColourStats st = colourStats(reference);
  return {{"lit_pixels", st.lit_pixels},
          {"mean_chroma", st.mean_chroma},
          {"mean_albedo_chroma", st.mean_albedo_chroma},
          {"grey_fraction", st.grey_fraction},
          {"hue_error_deg", st.hue_error_deg}};
}

// Who deviates, among the renderers that can express the scene (their
// pairs' verdicts), and which cannot; `blamed` gets the ids of those a
// majority deviates from (renderers::deviating).
std::string attribution(const std::vector<const renderers::Renderer*>& rs, const std::vector<int>& verdict,
                        const Renders& renders, std::vector<std::string>& blamed) {
  std::vector<const renderers::Renderer*> can;
  std::vector<std::string> cannot;
  for (const auto* r : rs) {
    if (notExpressible(renders.at(r->id))) cannot.push_back(r->display_name);
    else can.push_back(r);
  }
  const std::string not_expr = cannot.empty() ? "" : renderers::joinNames(cannot) + " cannot express it";
  if (can.size() < 2) return "nothing to compare" + (not_expr.empty() ? std::string() : ": " + not_expr);
  // The pairs of `can`, in unorderedPairs(can.size()) order: the pairs of
  // rs without a renderer that cannot express the scene, in their order.
  std::vector<int> can_verdict;
  const std::vector<renderers::RendererPair> pairs = renderers::unorderedPairs(rs.size());
  for (size_t p = 0; p < pairs.size(); ++p)
    if (!notExpressible(renders.at(rs[pairs[p].a]->id)) && !notExpressible(renders.at(rs[pairs[p].b]->id)))
      can_verdict.push_back(verdict[p]);
  const std::string who = renderers::attribute(can, can_verdict);
  for (size_t k : renderers::deviating(can.size(), can_verdict)) blamed.push_back(can[k]->id);
  return not_expr.empty() ? who : who + "; " + not_expr;
}

// A geometry check (geometry_checks.h): the job's passes against the
// reference's passes its job wrote beside them (plan.h), with the check's
// bounds. Both are read here, never rendered: the compare step compares.
J geometryCheck(const Plan& plan, const RenderJob& job, const Render& r) {
  const std::string against = renderers::registry().reference().id;
  if (!r.error.empty()) return geometryCheckError(job.renderer, against, r.error);
  if (notExpressible(r)) return geometryCheckNotExpressible(job.renderer, against, r.rec.not_expressible);
  const fs::path ref_file = plan.dir / job.reference_passes();
  GeometryPasses ref, other;
  try {
    ref = geometryPassesFromImage(readImage(ref_file));
  } catch (const std::exception& e) {
    return geometryCheckError(job.renderer, against,
                              ref_file.string() + ": the reference's passes cannot be read: " + e.what());
  }
  try {
    other = geometryPassesFromImage(r.image);
    return geometryCheckCompared(job.renderer, against, compareGeometry(ref, other), kGeometryTolerance);
  } catch (const std::exception& e) {
    return geometryCheckError(job.renderer, against, (plan.dir / job.exr()).string() + ": " + e.what());
  }
}

// The names (no folder) of the comparison outputs (compare_outputs.h) a
// case's pairs name: each compared pair's difference EXR (a pair with
// metrics was compared; results.json names its heat map, not the EXR), its
// heat and bound maps and its crops.
std::set<std::string> namedOutputs(const J& pairs) {
  std::set<std::string> named;
  const auto add = [&named](const J& rel) { named.insert(fs::path(rel.get<std::string>()).filename().string()); };
  for (const J& jp : pairs) {
    if (jp.contains("metrics")) named.insert(diffExrName(jp["pair"].get<std::string>()));
    for (const char* key : {"heat_map", "bound_map"})
      if (jp.contains(key)) add(jp[key]);
    if (!jp.contains("crops")) continue;
    for (const auto& [pixel, crop] : jp["crops"].items()) {
      add(crop["heat_map"]);
      for (const auto& [id, png] : crop["renders"].items()) add(png);
    }
  }
  return named;
}

// The case of plan.scenes[k]: its renders, every pair of them, who deviates.
// Then the comparison outputs of its folder that its pairs do not name (an
// earlier run's: a pair that no longer fails or no longer exists) are
// removed, their names into `removed`.
J compareCase(const CompareContext& cx, size_t k, std::vector<std::string>& removed) {
  const Plan& plan = cx.plan;
  const PlannedScene& ps = plan.scenes[k];
  const Scene scene = loadScene(ps.path, plan.budget);
  if (scene.name != ps.name)
    throw std::runtime_error(ps.path.string() + ": name: \"" + scene.name + "\": the plan (" +
                             planFile(plan.dir).string() + ") says \"" + ps.name + "\": plan again");
  makeRealFolder(plan.dir, plan.dir / ps.name);  // the diff images go there: never through a link
  J jc = {{"scene", ps.name}, {"file", ps.file}, {"reproduce", reproduceCommand(plan, ps)}};
  Renders renders;
  // The case's image renderers, in job (registry) order: its pairs and the
  // attribution are theirs. Its geometry checks (geometry_checks.h) are
  // compared apart, each with the reference's passes.
  std::vector<const renderers::Renderer*> rs;
  std::vector<const RenderJob*> geometry_jobs;
  jc["renders"] = J::object();
  for (size_t j : sceneJobs(plan, k)) {
    const RenderJob& job = plan.jobs[j];
    const renderers::Renderer& r = renderers::registry().at(job.renderer);
    if (r.geometry_passes) geometry_jobs.push_back(&job);
    else rs.push_back(&r);
    renders[job.renderer] = loadRender(plan, job, cx.images);
    jc["renders"][job.renderer] = renderJson(job, renders[job.renderer]);
  }
  for (const LeftOut& l : ps.left_out)
    if (!leftOutUnsaid(l)) jc["left_out"][l.renderer] = l.reason;
  // The scene's warnings (lint/scene_lint.h): recorded, never part of the verdict.
  for (const SceneWarning& w : lintScene(scene))
    jc["warnings"].push_back({{"code", w.code}, {"subject", w.subject}, {"message", w.message}});
  const std::vector<renderers::RendererPair> pairs = renderers::unorderedPairs(rs.size());
  std::vector<int> verdict(pairs.size());
  J jpairs = J::array();
  int compare_errors = 0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    jpairs.push_back(comparePair(cx, scene, *rs[pairs[p].a], *rs[pairs[p].b], renders, verdict[p]));
    if (verdict[p] == kCompareError) ++compare_errors, verdict[p] = kRenderError;
    jpairs.back()["verdict"] = results::pairVerdictName(pairVerdict(verdict[p]));
  }
  jc["pairs"] = jpairs;
  removed = removeStaleCompareOutputs(plan.dir / ps.name, namedOutputs(jpairs));
  const auto ref = renders.find(renderers::registry().reference().id);
  if (ref != renders.end() && ref->second.error.empty() && !notExpressible(ref->second))
    jc["colour_stats"] = colourStatsJson(ref->second.image);
  J checks = J::array();
  for (const RenderJob* job : geometry_jobs) checks.push_back(geometryCheck(plan, *job, renders[job->renderer]));
  if (!geometry_jobs.empty()) jc["geometry_checks"] = checks;
  // Who deviates among the image renderers, then each geometry check that
  // failed (it says nothing about the image renderers: it checks what they
  // all read, the loaded model, against Blender's own import).
  std::vector<std::string> blamed;
  // A finding's pair differs as declared: for who deviates, a failure.
  std::vector<int> differ = verdict;
  std::replace(differ.begin(), differ.end(), kFinding, kFail);
  std::string who = attribution(rs, differ, renders, blamed);
  for (const auto& finding : scene.findings) {
    const std::string& id = finding.first;  // a name a lambda can capture (not a structured binding)
    if (std::any_of(jpairs.begin(), jpairs.end(), [&id](const J& p) {
          return p.value("verdict", "") == "finding" && p["finding"]["renderer"] == id;
        }))
      who += "; " + renderers::registry().at(id).display_name + " differs as the scene's finding declares";
  }
  const std::string nothing = "nothing to compare";
  if (who.rfind(nothing, 0) == 0 && geometryChecksWith(checks, "pass") + geometryChecksWith(checks, "fail") > 0)
    who = "no image pair to compare" + who.substr(nothing.size());
  for (const J& c : checks)
    if (c["verdict"] == "fail")
      who += "; " + renderers::registry().at(c["renderer"].get<std::string>()).display_name +
             " and the reference disagree in geometry (the model loader or the import)";
  jc["attribution"] = who;
  if (!blamed.empty()) jc["deviating"] = blamed;
  // The case's verdict, once (case_verdict.h): on its renders' errors, the
  // pairs and geometry checks it compared and how they came out.
  CaseTally tally;
  for (const auto& [id, r] : renders) tally.errors += !r.error.empty();
  tally.errors += compare_errors;
  tally.errors += geometryChecksWith(checks, "error");
  tally.failed = static_cast<int>(std::count(verdict.begin(), verdict.end(), kFail) +
                                  std::count(verdict.begin(), verdict.end(), kFailOnlyFraction)) +
                 geometryChecksWith(checks, "fail");
  // A finding that holds is the outcome the scene declares: it counts as passed.
  tally.passed = static_cast<int>(std::count(verdict.begin(), verdict.end(), kPass) +
                                  std::count(verdict.begin(), verdict.end(), kFinding)) +
                 geometryChecksWith(checks, "pass");
  const CaseVerdict v = caseVerdict(tally);
  jc["verdict"] = verdictName(v);
  jc["pass"] = v == CaseVerdict::Pass;
  return jc;
}

// "1 scene", "3 scenes".
std::string counted(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// A case's verdict in a progress line: "pass", else in capitals ("FAIL",
// "NOT COMPARED").
std::string progressWord(CaseVerdict v) {
  std::string word = verdictName(v);
  if (v == CaseVerdict::Pass) return word;
  for (char& ch : word) ch = ch == '_' ? ' ' : static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return word;
}

// The case of plan.scenes[k] when comparing it threw: an error, saying why.
J failedCase(const Plan& plan, size_t k, const std::exception_ptr& failure) {
  std::string why;
  try {
    std::rethrow_exception(failure);
  } catch (const std::exception& e) {
    why = e.what();
  } catch (...) {
    why = "an unknown exception";
  }
  const PlannedScene& ps = plan.scenes[k];
  return {{"scene", ps.name},
          {"file", ps.file},
          {"reproduce", reproduceCommand(plan, ps)},
          {"renders", J::object()},
          {"pairs", J::array()},
          {"attribution", "error: the case could not be compared: " + why},
          {"verdict", verdictName(CaseVerdict::Error)},
          {"pass", false}};
}

}  // namespace

struct CaseComparer::State {
  const Plan& plan;
  J jsections;
  CompareContext cx;
  std::vector<J> compared;
  std::vector<std::exception_ptr> failed;
  std::mutex lock;  // the progress count and lines
  size_t done = 0;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
};

CaseComparer::CaseComparer(const Plan& plan, const ReportSections& sections, ImageHandoff* images) {
  J jsections = sectionsJson(sections, plan.dir);  // fails early on a folder with no results
  // The old verdict must not outlive this run: whatever stops it from here
  // on (an error, a kill) leaves no results.json or report.html at all.
  removeVerdict(plan);
  state_.reset(new State{plan, std::move(jsections), CompareContext{plan, loadTolerances(plan.tolerances_path), images},
                         std::vector<J>(plan.scenes.size()), std::vector<std::exception_ptr>(plan.scenes.size())});
}

CaseComparer::~CaseComparer() = default;

void CaseComparer::compare(size_t k) {
  State& st = *state_;
  const auto t0 = std::chrono::steady_clock::now();
  // The cases are independent (each reads its own renders and writes into
  // its own folder); each result goes to its own slot.
  std::string verdict;
  std::vector<std::string> removed;
  try {
    st.compared.at(k) = compareCase(st.cx, k, removed);
    verdict = progressWord(parseCaseVerdict(st.compared[k]["verdict"].get<std::string>(), "verdict"));
  } catch (...) {
    st.failed.at(k) = std::current_exception();
    verdict = "ERROR";
  }
  const auto t1 = std::chrono::steady_clock::now();
  std::lock_guard<std::mutex> g(st.lock);
  std::fprintf(stderr, "[compared %zu/%zu] %-32s %-12s %6.2f s   elapsed %.0f s\n", ++st.done, st.plan.scenes.size(),
               st.plan.scenes[k].name.c_str(), verdict.c_str(), std::chrono::duration<double>(t1 - t0).count(),
               std::chrono::duration<double>(t1 - st.t0).count());
  if (!removed.empty())
    std::fprintf(stderr,
                 "xval validate: %s: removed %zu stale comparison outputs (diff_*.exr, heat_*.png, crop_*.png) "
                 "of an earlier run that this run's results do not name\n",
                 (st.plan.dir / st.plan.scenes[k].name).c_str(), removed.size());
}

int CaseComparer::finish() {
  State& st = *state_;
  const Plan& plan = st.plan;
  const fs::path& dir = plan.dir;
  // A case that threw (its scene file cannot be read any more, a file of
  // its folder cannot be written) is that case's error, with the message
  // that names the file: the other cases are still reported.
  for (size_t k = 0; k < plan.scenes.size(); ++k)
    if (st.failed[k]) st.compared[k] = failedCase(plan, k, st.failed[k]);
  J jcases = J::array();
  std::vector<fs::path> setting_files{plan.tolerances_path};
  for (size_t k = 0; k < plan.scenes.size(); ++k) {
    if (st.compared[k].is_null())
      throw std::logic_error("the compare step: case " + plan.scenes[k].name + " was not compared");
    setting_files.push_back(plan.scenes[k].path);
    jcases.push_back(std::move(st.compared[k]));
  }
  // The results as their types (results/results.h): the summary below reads
  // the verdicts stored there, and the one writer writes them, with bytes
  // that are no UTF-8 (tools' logs, files' names) as U+FFFD: never a
  // results.json that cannot be written.
  const fs::path results_file = dir / "results.json";
  const results::Results res =
      results::resultsFromJson(resultsJson(plan, jcases, setting_files, st.jsections), results_file.string());
  std::map<CaseVerdict, int> cases;  // by verdict
  std::vector<CaseVerdict> verdicts;
  int not_expressible = 0, not_compared = 0;  // image renders, and their pairs
  std::map<results::PairVerdict, int> checks;  // geometry checks by verdict
  for (const results::Case& c : res.cases) {
    for (const auto& [id, r] : c.renders) not_expressible += r.not_expressible.has_value();
    for (const results::Pair& p : c.pairs) not_compared += p.verdict == results::PairVerdict::NotExpressible;
    // A check's not-expressible render is the check's verdict, counted
    // with the checks, not with the image renders.
    for (const results::GeometryCheck& g : c.geometry_checks)
      not_expressible -= g.verdict == results::PairVerdict::NotExpressible, ++checks[g.verdict];
    if (!c.verdict) throw std::logic_error("the compare step: case " + c.scene + " has no verdict");
    verdicts.push_back(*c.verdict);
    ++cases[verdicts.back()];
  }
  const int checks_pass = checks[results::PairVerdict::Pass], checks_fail = checks[results::PairVerdict::Fail],
            checks_error = checks[results::PairVerdict::Error],
            checks_nexp = checks[results::PairVerdict::NotExpressible];
  results::writeResults(results_file, res);
  writeReport(dir / "results.json", dir / "report.html");
  printNextSteps(plan, res.cases);
  // "3 scenes, all pass", else the worst verdict and every verdict's count:
  // "3 scenes, ERRORS: 1 error, 1 fail, 1 not compared".
  const int status = validateExitStatus(verdicts);
  std::string line = counted(res.cases.size(), "scene", "scenes") + ", ";
  if (status == 0) {
    line += "all pass";
  } else {
    line += cases[CaseVerdict::Error] ? "ERRORS: " : cases[CaseVerdict::Fail] ? "FAIL: " : "NOT COMPARED: ";
    std::string counts;
    for (const auto& [v, one, many] : {std::tuple{CaseVerdict::Error, "error", "errors"},
                                       std::tuple{CaseVerdict::Fail, "fail", "fail"},
                                       std::tuple{CaseVerdict::NotCompared, "not compared", "not compared"},
                                       std::tuple{CaseVerdict::Pass, "pass", "pass"}})
      if (cases[v]) counts += (counts.empty() ? "" : ", ") + counted(cases[v], one, many);
    line += counts;
  }
  if (not_expressible)
    line += " (" + counted(not_expressible, "render", "renders") + " not expressible, " +
            counted(not_compared, "pair", "pairs") + " not compared)";
  if (checks_pass + checks_fail + checks_error + checks_nexp > 0)
    line += "; geometry checks: " + std::to_string(checks_pass) + " pass, " + std::to_string(checks_fail) + " fail, " +
            counted(checks_error, "error", "errors") + ", " + std::to_string(checks_nexp) + " not expressible";
  std::fprintf(stderr, "xval validate: %s; wrote %s\n", line.c_str(), (dir / "report.html").c_str());
  return status;
}

int compareAndReport(const Plan& plan, const ReportSections& sections, int workers) {
  CaseComparer comparer(plan, sections);
  // `workers` cases at once; kept in plan order (CaseComparer).
  runJobPool(plan.scenes.size(), workers, [&](size_t k) { comparer.compare(k); });
  return comparer.finish();
}

}  // namespace xval::validation
