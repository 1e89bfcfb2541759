// xval crosscheck (crosscheck.h): validate's run of one scene and one
// pair, then the pair's verdict from the typed results.
#include "validate/validation/crosscheck.h"

#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>

#include "files/atomic_write.h"
#include "image/pixel_classes.h"
#include "renderers/registry.h"
#include "validate/tolerances.h"
#include "validate/validation/plan.h"
#include "validate/validation/validate_run.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;

fs::path normal(const fs::path& p) { return fs::absolute(p).lexically_normal(); }

// The case of the crosschecked scene among the folder's (an earlier run's
// cases are kept, validate/validation/plan_update.h).
const results::Case& crosscheckedCase(const results::Results& r, const CrosscheckRequest& request,
                                      const fs::path& results_file) {
  for (const results::Case& c : r.cases)
    if (normal(c.file) == normal(request.scene_file)) return c;
  throw std::runtime_error(results_file.string() + ": cases: no case of " + request.scene_file);
}

double secondsOf(const results::Case& c, const std::string& id) {
  const results::Render* r = c.render(id);
  return r ? r->seconds : 0.0;
}

// "shading 0, silhouette 2, ..." of the over-tolerance counts (as
// image/compare.h classCountsText writes them from the compare).
std::string classCountsText(const results::PairMetrics& m) {
  std::string s;
  for (const PixelClassInfo& info : kPixelClasses)
    for (const auto& [key, n] : m.over_tolerance)
      if (key == info.key) s += (s.empty() ? "" : ", ") + std::string(info.name) + " " + std::to_string(n);
  return s;
}

long long overTotal(const results::PairMetrics& m) {
  for (const auto& [key, n] : m.over_tolerance)
    if (key == "total") return n;
  return 0;
}

double orInfinity(const std::optional<double>& v) { return v ? *v : std::numeric_limits<double>::infinity(); }

// The verdict line of a compared image pair, and its failing criteria.
void printPair(const results::Case& c, const results::Pair& p, const std::string& ref, const std::string& id) {
  const results::PairMetrics& m = *p.metrics;
  const bool pass = p.verdict == results::PairVerdict::Pass;
  const char* word = pass ? "PASS" : p.verdict == results::PairVerdict::Finding ? "FINDING (differs as declared)" : "FAIL";
  std::printf(
      "%s vs %s: %s  max %.2f  p99.9 %.2f  RMSE %.3f (x/65535)  within %.6g: %.4f%% (need "
      "%.6g%%)  masks: %lld off (%lld explained by edges)  over tolerance: %lld (%s; max unexplained %.2f, "
      "cap %.6g)  time: reference %.2f s, %s %.2f s\n",
      c.scene.c_str(), id.c_str(), word, m.max_abs_16bit, m.p999_abs_16bit, m.rmse_16bit,
      m.tolerance.max_abs_16bit, 100 * m.fraction_within, 100 * m.tolerance.fraction, m.mask_disagree,
      m.mask_disagree_explained, overTotal(m), classCountsText(m).c_str(), orInfinity(m.max_unexplained_16bit),
      m.tolerance.max_unexplained_16bit, secondsOf(c, ref), id.c_str(), secondsOf(c, id));
  for (const PairFailure& f : p.failed) std::printf("  fails: %s\n", f.text.c_str());
  if (!m.tolerance_reason.empty()) std::printf("  declared tolerance: %s\n", m.tolerance_reason.c_str());
  if (p.finding)
    std::printf("  %s: %s: %s\n", p.finding->renderer.c_str(),
                p.verdict == results::PairVerdict::Finding ? "finding" : "finding no longer holds (within the tolerance)",
                p.finding->why.c_str());
}

// The verdict line of a compared geometry check.
void printCheck(const results::Case& c, const results::GeometryCheck& g) {
  const results::GeometryCheckMetrics& m = *g.metrics;
  const bool pass = g.verdict == results::PairVerdict::Pass;
  std::printf(
      "%s vs %s: %s  covered %lld  masks: %lld off (%lld on silhouettes)  depth: max rel %.3g (all %.3g)  "
      "uv: max %.3g over %lld (all %.3g)  depth edges %lld, edge pixels over: %lld%s%s\n",
      c.scene.c_str(), g.renderer.c_str(), pass ? "PASS" : "FAIL", m.covered, m.mask_disagree,
      m.mask_disagree_silhouette, m.max_depth_rel, m.max_depth_rel_all, m.max_uv, m.uv_compared, m.max_uv_all,
      m.depth_edges, m.edge_over, pass ? "" : ": ", pass ? "" : g.reason.value_or("").c_str());
}

// What the verdict of a pair or a check means for crosscheck: its line on
// stdout (or the error on stderr) and the exit status.
int report(const results::Case& c, results::PairVerdict verdict, const std::string& id, const std::string& why,
           const std::function<void()>& print_compared) {
  switch (verdict) {
    case results::PairVerdict::NotExpressible:
      std::printf("%s vs %s: NOT EXPRESSIBLE (not compared): %s\n", c.scene.c_str(), id.c_str(), why.c_str());
      return 0;
    case results::PairVerdict::Error:
      std::fprintf(stderr, "xval crosscheck: error: %s\n", why.c_str());
      return 2;
    case results::PairVerdict::Pass:
    case results::PairVerdict::Finding:  // the difference the scene declares
    case results::PairVerdict::Fail:
      print_compared();
      return verdict == results::PairVerdict::Fail ? 1 : 0;
  }
  return 2;
}

}  // namespace

int crosscheck(const CrosscheckRequest& request, results::Results& results) {
  const fs::path dir(request.dir);
  // A run that does not finish leaves no metrics.json that looks like its.
  std::error_code ec;
  if (!fs::remove(dir / "metrics.json", ec) && ec)
    throw std::runtime_error((dir / "metrics.json").string() + ": cannot remove the previous run's: " + ec.message());
  // The file validate's plan finds by the same rule (validate/tolerances.h),
  // said first as before any render, and recorded in metrics.json with how
  // it was found.
  const ToleranceFile tol_file = findToleranceFile(request.tolerances, {request.scene_file});
  std::printf("tolerances: %s\n", tol_file.describe().c_str());
  std::fflush(stdout);
  ValidateRequest v;
  v.inputs = {request.scene_file};
  v.output = request.dir;
  v.tolerances = request.tolerances;
  v.crosscheck_renderer = request.renderer;
  v.timeout_seconds = request.timeout_seconds;
  v.budget = request.budget;
  v.renderer_files = request.renderer_files;
  v.export_cache = false;  // as before: a crosscheck exports its scene afresh
  run(v);  // its exit status is the case's; a crosscheck's is its pair's (below)

  const std::vector<std::string> pair = crosscheckRenderers(request.renderer);
  const std::string& ref = pair[0];
  const std::string& id = pair[1];
  const fs::path results_file = normal(dir) / "results.json";
  const results::Results all = results::readResults(results_file);
  results = all;
  results.cases = {crosscheckedCase(all, request, results_file)};
  results::Case& c = results.cases.front();
  c.verdict.reset();  // a crosscheck's verdict is its pair's (JUnit: no "case" testcase)

  results::Json metrics = {{"scene", c.scene}, {"renderer", id}};
  int status = 2;
  if (renderers::registry().at(id).geometry_passes) {
    const results::GeometryCheck* g = nullptr;
    for (const results::GeometryCheck& check : c.geometry_checks)
      if (check.renderer == id) g = &check;
    if (!g) throw std::runtime_error(results_file.string() + ": " + c.scene + ": no geometry check of " + id);
    metrics.update(results::toJson(*g));
    status = report(c, g->verdict, id, g->reason.value_or(""), [&] { printCheck(c, *g); });
  } else {
    const results::Pair* p = c.findPair(renderers::pairKey(ref, id));
    if (!p) throw std::runtime_error(results_file.string() + ": " + c.scene + ": no pair " + ref + "-" + id);
    metrics.update(results::toJson(*p));
    const results::Render* r = c.render(id);
    // The renderer's own refusal, as the render record has it (the pair's
    // says which renderer refused).
    const std::string why = p->error                  ? *p->error
                            : r && r->not_expressible ? *r->not_expressible
                                                      : p->not_expressible.value_or("");
    status = report(c, p->verdict, id, why, [&] { printPair(c, *p, ref, id); });
  }
  metrics["tolerance_file"] = {{"path", tol_file.path.string()}, {"found_by", tol_file.found_by}};
  metrics["seconds"] = {{ref, secondsOf(c, ref)}, {id, secondsOf(c, id)}};
  writeFileAtomically(dir / "metrics.json", metrics.dump(2) + "\n");
  return status;
}

results::Results crosscheckError(const CrosscheckRequest& request, const std::string& error) {
  const renderers::Registry& registry = renderers::registry();
  const std::string ref = registry.reference().id;
  results::Case c;
  c.scene = fs::path(request.scene_file).stem().string();
  c.file = request.scene_file;
  // Not timed: the run stopped before its record (JUnit's time 0).
  results::Render render;
  render.error = error;
  c.renders.push_back({request.renderer, render});
  const renderers::Renderer* r = registry.find(request.renderer);
  if (r && r->geometry_passes) {
    results::GeometryCheck g;
    g.renderer = request.renderer;
    g.against = ref;
    g.verdict = results::PairVerdict::Error;
    g.reason = error;
    c.geometry_checks.push_back(g);
  } else {
    results::Pair p;
    p.pair = ref + "-" + request.renderer;
    p.verdict = results::PairVerdict::Error;
    p.error = error;
    c.pairs.push_back(p);
  }
  results::Results out;
  out.cases.push_back(std::move(c));
  return out;
}

}  // namespace xval::validation
