// The next steps of failing cases (next_steps.h).
#include "validate/validation/next_steps.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "golden/golden_set.h"
#include "image/pair_failure.h"
#include "process/shell_word.h"
#include "renderers/registry.h"
#include "validate/tolerances.h"
#include "validate/results/case_verdict.h"

namespace xval::validation {

namespace fs = std::filesystem;

namespace {

const PlannedScene& plannedScene(const Plan& plan, const std::string& name) {
  for (const PlannedScene& ps : plan.scenes)
    if (ps.name == name) return ps;
  throw std::runtime_error(planFile(plan.dir).string() + ": no scene \"" + name + "\" (results and plan disagree)");
}

// The id of renderer `id`'s golden set: golden for the reference, else golden-ID.
std::string goldenSetOf(const std::string& id) { return renderers::goldenSetIdOf(id); }

bool pairFailed(const results::Case& c, const std::string& a, const std::string& b) {
  for (const results::Pair& p : c.pairs)
    if ((p.pair == a + "-" + b || p.pair == b + "-" + a) && p.verdict == results::PairVerdict::Fail) return true;
  return false;
}

// The renderers of the case whose golden images are the step (next_steps.h).
std::vector<std::string> goldenStepRenderers(const results::Case& c, const PlannedScene& ps) {
  std::vector<std::string> out;
  for (const auto& [id, render] : c.renders) {
    const renderers::Renderer* r = renderers::registry().find(id);
    if (!r || r->geometry_passes || !r->images_of.empty()) continue;
    const bool deviates = std::find(c.deviating.begin(), c.deviating.end(), id) != c.deviating.end();
    if (!deviates && !pairFailed(c, id, goldenSetOf(id))) continue;
    try {
      if (golden::readManifest(golden::goldenFolder(ps.path, id), id).entries.count(ps.path.stem().string()))
        out.push_back(id);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "  (the golden set of %s cannot be read: %s)\n", id.c_str(), e.what());
    }
  }
  return out;
}

}  // namespace

std::string runOptions(const Plan& plan, const fs::path& scene_file) {
  std::string o;
  for (const RendererFile& f : plan.renderer_files) o += " --renderer-file " + shellPath(f.path);
  if (findToleranceFile("", {scene_file}).path != plan.tolerances_path)
    o += " --tolerances " + shellPath(plan.tolerances_path);
  return o;
}

std::string reproduceCommand(const Plan& plan, const PlannedScene& ps) {
  std::string c = "xval validate " + shellPath(ps.path) + " -o " +
                  shellPath(plan.dir / (ps.name + ".validate"));
  if (plan.renderers != jobRenderers()) {
    std::string list;
    for (const std::string& id : plan.renderers) list += (list.empty() ? "" : ",") + id;
    c += " --renderers " + shellWord(list);
  }
  return c + runOptions(plan, ps.path);
}

void printNextSteps(const Plan& plan, const std::vector<results::Case>& cases) {
  for (const results::Case& c : cases) {
    const std::string& scene = c.scene;
    if (!c.verdict) throw std::logic_error("printNextSteps: case " + scene + " has no verdict");
    const CaseVerdict v = *c.verdict;
    if (v == CaseVerdict::Pass) continue;
    if (v == CaseVerdict::NotCompared) {
      // Nothing to look closer at: say why nothing was compared.
      std::fprintf(stderr, "NOT COMPARED %s (%s)\n", scene.c_str(), c.attribution.c_str());
      for (const auto& [id, why] : c.left_out) std::fprintf(stderr, "  %s left out: %s\n", id.c_str(), why.c_str());
      continue;
    }
    const PlannedScene& ps = plannedScene(plan, scene);
    const std::string options = runOptions(plan, ps.path);
    std::fprintf(stderr, "%s %s (%s)\n", v == CaseVerdict::Error ? "ERROR" : "FAIL", scene.c_str(),
                 c.attribution.c_str());
    // Each failing pair, with every criterion it fails (image/pair_failure.h).
    for (const results::Pair& p : c.pairs)
      if (!p.failed.empty()) std::fprintf(stderr, "  %s fails: %s\n", p.pair.c_str(), failedText(p.failed).c_str());
    // Every renderer of the case that rendered it, but the reference.
    for (const auto& [id, render] : c.renders)
      if (id != renderers::registry().reference().id && !render.not_expressible)
        std::fprintf(stderr, "  look closer: xval crosscheck %s --renderer %s -o %s%s\n",
                     shellPath(ps.path).c_str(), shellWord(id).c_str(),
                     shellPath(plan.dir / (scene + "." + id)).c_str(), options.c_str());
    std::fprintf(stderr,
                 "  accept a documented difference: declare it, with its measured reason, in the\n"
                 "  `tolerances` field of %s (defaults: %s)\n",
                 ps.file.c_str(), plan.tolerances.c_str());
    for (const std::string& id : goldenStepRenderers(c, ps))
      std::fprintf(stderr,
                   "  after an intended change of %s, store its images anew:\n"
                   "  %s\n",
                   renderers::registry().at(id).sentenceSubject().c_str(),
                   renderers::goldenUpdateCommand(ps.path, id).c_str());
  }
}

}  // namespace xval::validation
