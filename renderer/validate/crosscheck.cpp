// xval crosscheck (crosscheck.h).
#include "validate/crosscheck.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "geometry/scene_meshes.h"
#include "image/compare.h"
#include "image/pair_failure.h"
#include "image/metric_table.h"
#include "image/perceptual.h"
#include "render/renderer.h"
#include "renderers/job_export.h"
#include "renderers/registry.h"
#include "lint/scene_lint.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "validate/tolerances.h"
#include "validate/geometry_check.h"
#include "validate/results/geometry_checks.h"
#include "render/geometry_passes.h"

namespace xval::validation {

int crosscheck(const CrosscheckRequest& request) {
  Scene scene = loadScene(request.scene_file, request.budget);
  printSceneWarnings("xval crosscheck", scene);
  for (const std::string& n : meshNotes(scene)) std::fprintf(stderr, "xval crosscheck: note: %s\n", n.c_str());
  std::filesystem::path dir(request.dir);
  std::filesystem::create_directories(dir);
  const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval crosscheck");
  std::filesystem::remove(dir / "metrics.json");
  // The one rule (validate/tolerances.h): --tolerances, else the nearest
  // tolerances.json at or above the scene, else the toolkit's own.
  const ToleranceFile tol_file = findToleranceFile(request.tolerances, {request.scene_file});
  const ToleranceTable table = loadTolerances(tol_file.path);
  std::printf("tolerances: %s\n", tol_file.describe().c_str());
  std::string reason;
  Tolerance tol = table.lookup(scene, request.renderer, &reason);
  const renderers::Renderer& renderer = renderers::registry().at(request.renderer);
  if (!renderers::meantFor(scene.renderers, renderer))
    throw std::runtime_error(request.scene_file + ": renderers: the scene is meant for " +
                             renderers::joinNames(scene.renderers) + " only, not " + renderer.id);
  // A renderer that declares it cannot express the scene: the verdict, with
  // its reason, and nothing rendered (no pair to compare, no failure). The
  // refusal of a renderer that exports is decided by writing the export its
  // render then reads (renderers/job_export.h).
  const std::filesystem::path work = dir / (request.renderer + ".work");
  makeFreshFolder(work);  // nothing from an earlier attempt, no planted link
  renderers::RenderRequest render_request{work, request.timeout_seconds, {}};
  if (const std::string why = renderers::refuseOrExport(renderer, scene, render_request); !why.empty()) {
    const nlohmann::json j = {{"scene", scene.name},
                              {"renderer", request.renderer},
                              {"not_expressible", why},
                              {"tolerance_file", {{"path", tol_file.path.string()}, {"found_by", tol_file.found_by}}}};
    writeFileAtomically(dir / "metrics.json", j.dump(2) + "\n");
    std::printf("%s vs %s: NOT EXPRESSIBLE (not compared): %s\n", scene.name.c_str(), request.renderer.c_str(),
                why.c_str());
    return 0;
  }

  if (renderer.geometry_passes) {
    // Geometry passes (validate/geometry_check.h): the reference's passes
    // of our loaded triangles against the renderer's; not the image
    // tolerances.
    const GeometryPasses ref = referenceGeometryPasses(scene);
    writeImage(toImage(ref), dir / "reference-passes.exr");
    renderers::RenderInfo info;
    const Image ext = renderer.render(scene, render_request, &info);
    writeImage(ext, dir / (request.renderer + ".exr"));
    const GeometryMetrics m = compareGeometry(ref, geometryPassesFromImage(ext));
    nlohmann::json j = toJson(m, kGeometryTolerance);
    j["scene"] = scene.name;
    j["renderer"] = request.renderer;
    j["seconds"] = {{request.renderer, info.seconds}};
    writeFileAtomically(dir / "metrics.json", j.dump(2) + "\n");
    std::printf(
        "%s vs %s: %s  covered %lld  masks: %lld off (%lld on silhouettes)  depth: max rel %.3g (all %.3g)  "
        "uv: max %.3g over %lld (all %.3g)  depth edges %lld, edge pixels over: %lld%s%s\n",
        scene.name.c_str(), request.renderer.c_str(), m.pass ? "PASS" : "FAIL", m.covered, m.mask_off,
        m.mask_off_silhouette, m.max_depth_rel, m.max_depth_rel_all, m.max_uv, m.uv_compared, m.max_uv_all,
        m.depth_edges, m.edge_over, m.pass ? "" : ": ", m.why.c_str());
    return m.pass ? 0 : 1;
  }

  // The reference on its exact double-precision path.
  const renderers::Renderer& reference = renderers::registry().reference();
  renderers::RenderInfo ref_info;
  Image ref = reference.render(scene, {{}, request.timeout_seconds, {}}, &ref_info);
  const double ref_s = ref_info.seconds;
  writeImage(ref, dir / (reference.id + ".exr"));
  renderers::RenderInfo info;
  Image ext = renderer.render(scene, render_request, &info);
  writeImage(ext, dir / (request.renderer + ".exr"));
  const PairMeasures measures =
      measurePair(ref, ext, tol, {renderers::precisionOf(reference), renderers::precisionOf(renderer)});
  const CompareMetrics& m = measures.compare;
  writeImage(differenceImage(ref, ext), dir / "diff.exr", kDifferenceExrCompression);
  nlohmann::json j = pairJson(measures, tol);
  const std::vector<PairFailure> failed = failedCriteria(m, tol);
  j["failed"] = failedJson(failed);
  j["scene"] = scene.name;
  j["renderer"] = request.renderer;
  j["tolerance_reason"] = reason;
  j["tolerance_file"] = {{"path", tol_file.path.string()}, {"found_by", tol_file.found_by}};
  j["seconds"] = {{reference.id, ref_s}, {request.renderer, info.seconds}};
  if (info.render_seconds >= 0) j["seconds"][request.renderer + "_render"] = info.render_seconds;
  writeFileAtomically(dir / "metrics.json", j.dump(2) + "\n");
  const bool pass = tol.passes(m);
  std::printf(
      "%s vs %s: %s  max %.2f  p99.9 %.2f  RMSE %.3f (x/65535)  within %.6g: %.4f%% (need "
      "%.6g%%)  masks: %lld off (%lld explained by edges)  over tolerance: %lld (%s; max unexplained %.2f, "
      "cap %.6g)  time: reference %.2f s, %s %.2f s\n",
      scene.name.c_str(), request.renderer.c_str(), pass ? "PASS" : "FAIL",
      m.max_abs * 65535, m.p999_abs * 65535, m.rmse * 65535, tol.max_abs * 65535,
      100 * m.fraction_within, 100 * tol.fraction, m.mask_disagree,
      m.mask_disagree_explained, m.over_tolerance, classCountsText(m).c_str(), m.max_unexplained * 65535,
      tol.max_unexplained * 65535, ref_s, request.renderer.c_str(), info.seconds);
  for (const PairFailure& f : failed) std::printf("  fails: %s\n", f.text.c_str());
  if (!reason.empty()) std::printf("  declared tolerance: %s\n", reason.c_str());
  return pass ? 0 : 1;
}

namespace {

// The run's one case as results.json has it (crosscheckAsResults).
nlohmann::json crosscheckCase(const CrosscheckRequest& request, const std::string& error) {
  using J = nlohmann::json;
  const std::string reference = renderers::registry().reference().id;
  const std::string pair = reference + "-" + request.renderer;
  J c = {{"scene", std::filesystem::path(request.scene_file).stem().string()},
         {"file", request.scene_file},
         {"renders", J::object()}};
  J p = {{"pair", pair}};
  std::string problem = error;
  std::string refusal;  // the renderer's, when it cannot express the scene
  const std::filesystem::path metrics_file = std::filesystem::path(request.dir) / "metrics.json";
  if (problem.empty()) {
    try {
      const J m = parseJsonText(readJsonFile(metrics_file, "crosscheck metrics"), metrics_file.string());
      c["scene"] = m.at("scene");
      if (m.contains("not_expressible")) {
        // The renderer's refusal: a verdict (JUnit <skipped>), nothing rendered.
        refusal = m.at("not_expressible").get<std::string>();
        p["not_expressible"] = request.renderer + ": " + refusal;
      } else {
        for (const auto& [who, seconds] : m.at("seconds").items())
          if (who == reference || who == request.renderer) c["renders"][who] = {{"seconds", seconds}};
        p["pass"] = m.at("pass");
        // An image pair's failing criteria (a geometry check's metrics
        // have none; the schema requires them of every image pair).
        if (m.contains("failed")) p["failed"] = m.at("failed");
        p["metrics"] = m;
      }
    } catch (const std::exception& e) {
      problem = metrics_file.string() + ": no usable metrics (" + e.what() + ")";
    }
  }
  if (!problem.empty()) {
    p = {{"pair", pair}, {"error", problem}};
    // Not timed: the run stopped before its record (JUnit's time 0).
    c["renders"][request.renderer] = {{"seconds", 0.0}, {"error", problem}};
  }
  const renderers::Renderer* r = renderers::registry().find(request.renderer);
  if (r && r->geometry_passes) {
    // A geometry check (validate/results/geometry_checks.h), as validate
    // records it: no image pair.
    J g;
    if (!problem.empty()) g = geometryCheckError(request.renderer, reference, problem);
    else if (!refusal.empty())
      g = geometryCheckNotExpressible(request.renderer, reference, refusal);
    else {
      const J& m = p["metrics"];
      g = {{"renderer", request.renderer},
           {"against", reference},
           {"verdict", m.at("pass").get<bool>() ? "pass" : "fail"}};
      if (!m.at("pass").get<bool>()) g["reason"] = m.at("why");
      g["metrics"] = J::object();
      const J keys = metricsJson(GeometryMetrics{});  // the metrics' names
      for (auto it = keys.begin(); it != keys.end(); ++it) g["metrics"][it.key()] = m.at(it.key());
      g["bounds"] = m.at("tolerance");
    }
    c["pairs"] = J::array();
    c["geometry_checks"] = J::array({g});
    return c;
  }
  c["pairs"] = J::array({p});
  return c;
}

results::Results asResults(const nlohmann::json& c, const std::filesystem::path& metrics_file) {
  return results::resultsFromJson(results::Json{{"cases", results::Json::array({results::Json::parse(c.dump())})}},
                                  metrics_file.string());
}

}  // namespace

results::Results crosscheckAsResults(const CrosscheckRequest& request, const std::string& error) {
  const std::filesystem::path metrics_file = std::filesystem::path(request.dir) / "metrics.json";
  // The case as the results types (results/results.h). A metrics.json the
  // types cannot read (a field missing or of another type) is the pair's
  // error, naming the file and the field, as one that cannot be parsed.
  try {
    return asResults(crosscheckCase(request, error), metrics_file);
  } catch (const std::runtime_error& e) {
    if (!error.empty()) throw;  // the error form is read whole: never here
    return asResults(crosscheckCase(request, metrics_file.string() + ": no usable metrics (" + e.what() + ")"),
                     metrics_file);
  }
}

}  // namespace xval::validation
