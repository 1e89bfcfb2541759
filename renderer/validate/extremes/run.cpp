// The extremes run (validate/extremes/run.h).
#include "validate/extremes/run.h"

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>

#include "common/export_common.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/heat_map.h"
#include "process/job_pool.h"
#include "renderers/registry.h"
#include "scene_file/scene_loader.h"
#include "validate/common/provenance.h"
#include "validate/extremes/matrix.h"
#include "validate/extremes/measure.h"
#include "validate/extremes/results_file.h"

namespace xval::extremes {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using J = nlohmann::ordered_json;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct CaseRun {
  Case c;
  Scene scene;
  ReferenceRender dbl, flt;
  std::map<std::string, External> external;
};

External renderExternal(const Scene& scene, const std::string& id, const fs::path& work, double timeout) {
  const renderers::Renderer& renderer = renderers::registry().at(id);
  External e;
  const auto t0 = Clock::now();
  try {
    renderers::RenderInfo info;
    e.image = renderer.render(scene, {work, timeout, {}}, &info);
    e.render_seconds = info.render_seconds;
    e.status = "ok";
  } catch (const ExportError& err) {
    e.status = "not renderable";
    e.reason = "not renderable by " + renderer.display_name + ": " + err.what();
  } catch (const std::exception& err) {
    e.status = "error";
    e.reason = renderer.display_name + " failed: " + err.what();
  }
  e.seconds = since(t0);
  return e;
}

// 1. The reference renderer, both precisions, one case at a time.
void renderReferences(std::vector<CaseRun>& runs, const fs::path& dir, int threads) {
  for (size_t k = 0; k < runs.size(); ++k) {
    CaseRun& r = runs[k];
    const fs::path cdir = dir / r.c.name;
    makeRealFolder(dir, cdir);
    r.dbl = renderReference(r.scene, Precision::Double, threads);
    r.flt = renderReference(r.scene, Precision::Float, threads);
    writeImage(r.dbl.image, cdir / "double.exr");
    writeImage(r.flt.image, cdir / "float.exr");
    writePreviewPng(r.dbl.image, cdir / "double.png", 360);
    writeHeatMap(r.dbl.image, r.flt.image, cdir / "heat_float.png");
    const CompareMetrics m = compareToReference(r.dbl.image, r.flt.image);
    std::fprintf(stderr,
                 "[%2zu/%zu] %-28s double %.2f s, float %.2f s; NaN/Inf %lld/%lld (double), "
                 "%lld/%lld (float); float vs double max %.2f p99.9 %.2f /65535, mask %lld\n",
                 k + 1, runs.size(), r.c.name.c_str(), r.dbl.seconds, r.flt.seconds, r.dbl.nonfinite.final_pixels,
                 r.dbl.nonfinite.raw_pixels, r.flt.nonfinite.final_pixels, r.flt.nonfinite.raw_pixels,
                 m.max_abs * 65535.0, m.p999_abs * 65535.0, m.mask_disagree);
  }
}

// 2. External renderers, `jobs` at a time.
void renderExternals(std::vector<CaseRun>& runs, const std::vector<std::string>& renderers, const fs::path& dir,
                     int jobs, double timeout) {
  struct Job {
    size_t k;
    std::string renderer;
  };
  std::vector<Job> todo;
  for (size_t k = 0; k < runs.size(); ++k)
    for (const auto& rr : renderers) todo.push_back({k, rr});
  std::mutex lock;
  size_t done = 0;
  const auto t_ext = Clock::now();
  runJobPool(todo.size(), jobs > 0 ? jobs : defaultWorkers(), [&](size_t j) {
    CaseRun& r = runs[todo[j].k];
    const std::string& rr = todo[j].renderer;
    External e;
    try {
      const fs::path work = dir / r.c.name / (rr + ".work");
      makeFreshFolder(work);  // nothing from an earlier attempt, no planted link
      e = renderExternal(r.scene, rr, work, timeout);
    } catch (const std::exception& err) {  // this job's error, not the run's
      e.status = "error";
      e.reason = err.what();
    }
    std::lock_guard<std::mutex> g(lock);
    const size_t n = ++done;
    const double el = since(t_ext);
    std::fprintf(stderr, "[%zu/%zu] %-28s %-8s %-14s %6.2f s   elapsed %.0f s, ~%.0f s left\n", n, todo.size(),
                 r.c.name.c_str(), rr.c_str(), e.status.c_str(), e.seconds, el,
                 el * double(todo.size() - n) / double(n));
    if (e.status != "ok") std::fprintf(stderr, "  %s\n", e.reason.c_str());
    r.external[rr] = std::move(e);
  });
}

// 3. One case's comparisons and files, as its JSON.
J compareCase(CaseRun& r, const std::vector<std::string>& renderers, const fs::path& dir, int& external_errors) {
  const fs::path cdir = dir / r.c.name;
  J jc = caseJson(r.c, dir.string(), r.scene.camera.width, r.scene.camera.height, r.dbl, r.flt,
                  compareToReference(r.dbl.image, r.flt.image));
  for (const auto& rr : renderers) {
    External& e = r.external[rr];
    J je = {{"status", e.status}, {"seconds", e.seconds}};
    if (e.render_seconds >= 0) je["render_seconds"] = e.render_seconds;
    if (e.status == "ok") {
      writeImage(e.image, cdir / (rr + ".exr"));
      writePreviewPng(e.image, cdir / (rr + ".png"), 360);
      writeHeatMap(r.dbl.image, e.image, cdir / ("heat_" + rr + ".png"));
      const NonFinite nf = countNonFinite(e.image);
      je["nonfinite"] = {{"final", nf.final_pixels}, {"raw", nf.raw_pixels}};
      je["metrics"] = metricsWithMap(compareToReference(r.dbl.image, e.image), r.c.name + "/heat_" + rr + ".png");
      je["preview"] = r.c.name + "/" + rr + ".png";
    } else {
      je["reason"] = e.reason;
      external_errors += e.status == "error";
    }
    jc["external"][rr] = je;
  }
  return jc;
}

}  // namespace

std::vector<std::string> externalRenderers() {
  std::vector<std::string> ids;
  for (const renderers::Renderer* r : renderers::registry().everySceneRenderers())
    if (!r->reference) ids.push_back(r->id);
  return ids;
}

int runExtremes(const ExtremesRun& a) {
  const auto t_start = Clock::now();
  const fs::path& dir = a.dir;
  const std::vector<Case> cases = selectCases(extremesMatrix({a.size}), a.only);
  const std::vector<std::string> known = externalRenderers();
  for (const auto& rr : a.renderers)
    if (std::find(known.begin(), known.end(), rr) == known.end()) {
      std::string expected;
      for (const auto& k : known) expected += (expected.empty() ? "" : " and/or ") + k;
      throw std::runtime_error("--renderers: expected " + expected + ", got " + rr);
    }
  fs::create_directories(dir);
  const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval extremes");
  fs::remove(dir / "extremes.json");  // a new run: no stale results
  fs::remove(dir / "extremes.md");
  makeRealFolder(dir, dir / "scenes");
  const auto files = writeCaseScenes(cases, dir / "scenes");
  std::vector<CaseRun> runs(cases.size());
  for (size_t k = 0; k < cases.size(); ++k) {
    runs[k].c = cases[k];
    runs[k].scene = loadScene(files[k]);  // the file as anyone would load it
  }
  std::string names;
  for (const auto& rr : a.renderers) names += (names.empty() ? "" : ",") + rr;
  std::fprintf(stderr, "xval extremes: %zu cases, %dx%d, reference renderer (double, float)%s\n", runs.size(),
               a.size, a.size, a.renderers.empty() ? "" : (", then " + names).c_str());
  renderReferences(runs, dir, a.threads);
  renderExternals(runs, a.renderers, dir, a.jobs, a.timeout);

  long long reference_nonfinite = 0;
  int external_errors = 0;
  J jcases = J::array();
  for (CaseRun& r : runs) {
    reference_nonfinite += r.dbl.nonfinite.total() + r.flt.nonfinite.total();
    jcases.push_back(compareCase(r, a.renderers, dir, external_errors));
  }
  writeHeatScalePng(dir / "heat_scale.png");
  J results;
  results["format"] = "xval-extremes/1";
  results["provenance"] = provenanceJson(collectProvenance(dir / "git.log"), a.command, a.renderers);
  results["size"] = a.size;
  results["wall_seconds"] = since(t_start);
  results["totals"] = {{"cases", runs.size()},
                       {"reference_nonfinite_pixels", reference_nonfinite},
                       {"external_errors", external_errors}};
  results["cases"] = jcases;
  writeFileAtomically(dir / "extremes.md", markdownTable(results));
  writeFileAtomically(dir / "extremes.json", results.dump(2) + "\n");
  std::fprintf(stderr,
               "xval extremes: wrote %s (%zu cases, %.0f s): reference renderer NaN/Inf pixels: "
               "%lld; external renderer errors: %d\n",
               (dir / "extremes.json").c_str(), runs.size(), since(t_start), reference_nonfinite, external_errors);
  if (external_errors) return 2;
  return reference_nonfinite ? 1 : 0;
}

}  // namespace xval::extremes
