// The compare step of `xval validate` (compare_step.h).
#include "validate/validation/compare_step.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/compare.h"
#include "image/image.h"
#include "image/perceptual.h"
#include "renderers/registry.h"
#include "scene/scene_loader.h"
#include "validate/colour_stats.h"
#include "validate/tolerances.h"
#include "validate/validation/job_record.h"
#include "validate/validation/next_steps.h"
#include "validate/validation/results_file.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;
using J = nlohmann::ordered_json;

// One renderer's render of a case: its image, or why there is none.
struct Render {
  JobRecord rec;
  Image image;
  std::string error;
};
using Renders = std::map<std::string, Render>;  // by renderer id

// What every case is compared with.
struct CompareContext {
  const Plan& plan;
  const ToleranceTable table;
  const std::vector<const renderers::Renderer*> renderers;  // the every-scene ones, in registry order
  const std::vector<renderers::RendererPair> pairs;         // unorderedPairs(renderers.size())
};

// The job's render: its record checked against the plan, then its EXR.
Render loadRender(const Plan& plan, const RenderJob& job) {
  Render r;
  r.rec = readRecord(plan, job);
  if (!r.rec.present) {
    r.error = "not rendered: " + r.rec.problem;
  } else if (!r.rec.error.empty()) {
    r.error = r.rec.error;
  } else if (r.rec.input_hash != job.input_hash) {
    r.error = (plan.dir / job.record()).string() + ": rendered from other inputs (input_hash " +
              r.rec.input_hash + ", the plan's is " + job.input_hash + "): run the job again";
  } else {
    try {
      r.image = readImage(plan.dir / job.exr());
    } catch (const std::exception& e) {
      r.error = std::string("the record says ok but the image cannot be read: ") + e.what();
    }
  }
  return r;
}

// results.json's cases[].renders.<id>.
J renderJson(const RenderJob& job, const Render& r) {
  J jr = {{"seconds", r.rec.seconds}, {"image", job.png()}};
  if (r.rec.render_seconds >= 0) jr["render_seconds"] = r.rec.render_seconds;
  if (!r.error.empty()) jr["error"] = r.error;
  return jr;
}

// One pair of one case: compared with its tolerance, its difference EXR
// and heat map written. verdict: 1 pass, 0 fail, -1 not compared.
J comparePair(const CompareContext& cx, const Scene& scene, const RenderJob& j0, const renderers::RendererPair& pair,
              Renders& renders, int& verdict) {
  const renderers::Renderer& ra = *cx.renderers[pair.a];
  const renderers::Renderer& rb = *cx.renderers[pair.b];
  Render& A = renders[ra.id];
  Render& B = renders[rb.id];
  const std::string key = renderers::pairKey(ra, rb);
  J jp = {{"pair", key}};
  if (!A.error.empty() || !B.error.empty()) {
    verdict = -1;
    jp["error"] = "not compared: a render failed";
    return jp;
  }
  std::string reason;
  const Tolerance tol = cx.table.lookupPair(scene, ra.id, rb.id, &reason);
  if (!ra.reference && !rb.reference) {
    // The reference's diagnostics describe the same pixels.
    const Image& ref = renders[renderers::registry().reference().id].image;
    A.image.depth = ref.depth;
    A.image.backfacing = ref.backfacing;
    A.image.incidence = ref.incidence;
  }
  CompareMetrics m = compareImages(A.image, B.image, tol);
  PerceptualMetrics pm = perceptualMetrics(A.image, B.image);
  const Image diff = differenceImage(A.image, B.image);
  writeImage(diff, cx.plan.dir / j0.scene / ("diff_" + key + ".exr"));
  jp["heat_map"] = writeHeatMapPng(diff, cx.plan.dir, j0.scene, key);  // the report only shows it
  J jm = J::parse(toJson(m, tol, &pm));
  jm["tolerance_reason"] = reason;
  jp["metrics"] = jm;
  jp["pass"] = tol.passes(m);
  // Known differences are the classified ones and a declared reason.
  jp["classification"] = {{"known", m.over_occlusion_edge + m.over_backfacing + m.over_grazing},
                          {"unexplained", m.over_unexplained},
                          {"declared", !reason.empty()}};
  verdict = tol.passes(m) ? 1 : 0;
  return jp;
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

// The case of the scene whose jobs start at plan.jobs[first] (one per
// renderer, in registry order).
J compareCase(const CompareContext& cx, size_t first) {
  const Plan& plan = cx.plan;
  const RenderJob& j0 = plan.jobs[first];
  const Scene scene = loadScene(j0.path, plan.budget);
  if (scene.name != j0.scene)
    throw std::runtime_error(j0.path.string() + ": name: \"" + scene.name + "\": the plan (" +
                             planFile(plan.dir).string() + ") says \"" + j0.scene + "\": plan again");
  makeRealFolder(plan.dir, plan.dir / j0.scene);  // the diff images go there: never through a link
  J jc = {{"scene", j0.scene}, {"file", j0.file}};
  Renders renders;
  for (size_t r = 0; r < cx.renderers.size(); ++r) {
    const RenderJob& job = plan.jobs[first + r];
    renders[job.renderer] = loadRender(plan, job);
    jc["renders"][job.renderer] = renderJson(job, renders[job.renderer]);
  }
  std::vector<int> verdict(cx.pairs.size());
  J jpairs = J::array();
  for (size_t p = 0; p < cx.pairs.size(); ++p) jpairs.push_back(comparePair(cx, scene, j0, cx.pairs[p], renders, verdict[p]));
  jc["pairs"] = jpairs;
  const Render& reference = renders[renderers::registry().reference().id];
  if (reference.error.empty()) jc["colour_stats"] = colourStatsJson(reference.image);
  jc["attribution"] = renderers::attribute(cx.renderers, verdict);
  jc["pass"] = std::all_of(verdict.begin(), verdict.end(), [](int v) { return v == 1; });
  return jc;
}

bool anyRenderError(const J& jc) {
  for (const auto& [id, jr] : jc["renders"].items())
    if (jr.contains("error")) return true;
  return false;
}

}  // namespace

int compareAndReport(const Plan& plan, const ReportSections& sections) {
  const fs::path& dir = plan.dir;
  const J jsections = sectionsJson(sections, dir);  // fails early on a folder with no results
  // The old verdict must not outlive this run: whatever stops it from here
  // on (an error, a kill) leaves no results.json or report.html at all.
  removeVerdict(plan);
  const std::vector<const renderers::Renderer*> rs = renderers::registry().everySceneRenderers();
  const CompareContext cx{plan, loadTolerances(plan.tolerances_path), rs, renderers::unorderedPairs(rs.size())};
  bool any_error = false, any_fail = false;
  J jcases = J::array();
  std::vector<fs::path> setting_files{plan.tolerances_path};
  for (size_t first = 0; first < plan.jobs.size(); first += rs.size()) {
    setting_files.push_back(plan.jobs[first].path);
    J jc = compareCase(cx, first);
    any_error |= anyRenderError(jc);
    any_fail |= !jc["pass"].get<bool>();
    jcases.push_back(std::move(jc));
  }
  writeFileAtomically(dir / "results.json", resultsJson(plan, jcases, setting_files, jsections).dump(2) + "\n");
  writeReport(dir / "results.json", dir / "report.html");
  printNextSteps(plan, jcases);
  std::fprintf(stderr, "xval validate: %zu scenes, %s; wrote %s\n", jcases.size(),
               any_error ? "ERRORS" : any_fail ? "some cases FAIL" : "all pass", (dir / "report.html").c_str());
  return any_error ? 2 : any_fail ? 1 : 0;
}

}  // namespace xval::validation
