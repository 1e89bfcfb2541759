// xval golden update / check (validate/golden/golden_run.h).
#include "validate/golden/golden_run.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "files/output_folder.h"
#include "files/scratch_folder.h"
#include "golden/golden_set.h"
#include "image/compare.h"
#include "image/metric_criteria.h"
#include "image/pair_failure.h"
#include "process/run_process.h"
#include "process/shell_word.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_set.h"
#include "validate/common/provenance.h"
#include "validate/tolerances.h"

namespace xval::validation {

namespace fs = std::filesystem;

namespace {

const renderers::Renderer& sourceRenderer(const std::string& id) {
  const renderers::Renderer& r = renderers::registry().at(id);
  if (renderers::isGoldenSetId(r.id))
    throw std::runtime_error("--renderer " + id + ": a golden set cannot store golden images of itself");
  if (r.geometry_passes)
    throw std::runtime_error("--renderer " + id + ": its images are geometry passes, compared only by crosscheck "
                             "with the reference's passes: no golden set");
  return r;
}

std::string goldenSetId(const renderers::Renderer& r) { return renderers::goldenSetIdOf(r.id); }

// The render golden images are made of, and the settings it used.
struct Render {
  Image image;
  nlohmann::json settings;
};

Render renderForGolden(const renderers::Renderer& r, const Scene& scene, const fs::path& work, double timeout,
                      Precision precision = Precision::Double) {
  if (r.reference) {
    RenderOptions o = defaultOptions(scene);
    o.precision = precision;
    o.diagnostics = true;
    o.cull_back_faces = true;
    o.progress = false;
    return {r.render(scene, {work, timeout, o}, nullptr), golden::settingsOf(r.id, o.spp, toString(o.precision))};
  }
  return {r.render(scene, {work, timeout, {}}, nullptr), golden::settingsOf(r.id, 0, "")};
}

}  // namespace

int goldenUpdate(const GoldenRequest& request) {
  const renderers::Renderer& r = sourceRenderer(request.renderer);
  const std::vector<fs::path> files = sceneFiles(request.inputs, "xval golden");
  const renderers::Availability a = renderers::registry().availability(r.id);
  if (!a.available) throw std::runtime_error(r.display_name + " is not available: " + a.reason);
  const ScratchFolder scratch("golden");
  const Provenance prov = collectProvenance(scratch.dir() / "git.log");
  const std::string version = renderers::registry().version(r.id);
  std::map<fs::path, golden::Manifest> manifests;
  for (const fs::path& file : files) {
    const Scene scene = loadScene(file, request.budget);
    const fs::path folder = golden::goldenFolder(file, r.id);
    // SET/golden and SET/golden/<renderer> are real folders, never links
    // (as validate's output folder): a link there would receive the images
    // and the manifest outside the set.
    makeRealFolder(folder.parent_path().parent_path(), folder);
    auto it = manifests.find(folder);
    if (it == manifests.end()) it = manifests.emplace(folder, golden::readManifest(folder, r.id)).first;
    const std::string scene_hash = sha256File(file);
    const fs::path work = scratch.dir() / ("work-" + attemptToken());
    fs::create_directories(work);
    Render fresh = renderForGolden(r, scene, work, request.timeout_seconds);
    const std::string stem = file.stem().string();
    const fs::path image = folder / (stem + ".exr");
    golden::writeGoldenImage(fresh.image, image);
    golden::Entry& e = it->second.entries[stem];
    e.scene_file = fs::absolute(file).lexically_normal().lexically_relative(folder).generic_string();
    e.scene_sha256 = scene_hash;
    e.settings = fresh.settings;
    e.settings_sha256 = golden::settingsHash(fresh.settings);
    e.image = image.filename().string();
    e.image_sha256 = sha256File(image);
    e.renderer_version = version;
    e.git_commit = prov.git_commit;
    e.date_utc = prov.date_utc;
    golden::writeManifest(folder, it->second);
    std::printf("stored %s (%s) -> %s\n", file.string().c_str(), r.id.c_str(), image.string().c_str());
  }
  return 0;
}

int goldenCheck(const GoldenRequest& request) {
  const renderers::Renderer& r = sourceRenderer(request.renderer);
  const std::string set_id = goldenSetId(r);
  if (request.precision != "double" && request.precision != "float")
    throw std::runtime_error("--precision " + request.precision + ": expected double or float");
  const Precision precision = request.precision == "float" ? Precision::Float : Precision::Double;
  if (precision == Precision::Float && !r.reference)
    throw std::runtime_error("--precision float: applies to the reference renderer only");
  const std::vector<fs::path> files = sceneFiles(request.inputs, "xval golden");
  const renderers::Availability a = renderers::registry().availability(r.id);
  if (!a.available) throw std::runtime_error(r.display_name + " is not available: " + a.reason);
  const ToleranceFile tf = findToleranceFile(request.tolerances, files);
  const ToleranceTable table = loadTolerances(tf.path);
  std::printf("tolerances: %s\n", tf.describe().c_str());
  const ScratchFolder scratch("golden");
  int failed = 0;
  for (const fs::path& file : files) {
    const Scene scene = loadScene(file, request.budget);
    const fs::path folder = golden::goldenFolder(file, r.id);
    const golden::Manifest m = golden::readManifest(folder, r.id);
    auto fail = [&](const std::string& why) {
      ++failed;
      std::printf("FAIL %s (%s): %s\n", file.string().c_str(), request.precision.c_str(), why.c_str());
      // The golden images are of the exact path: only its render can be
      // accepted as one.
      if (precision == Precision::Double)
        std::printf("  accept the fresh render: %s\n", renderers::goldenUpdateCommand(file, r.id).c_str());
      else
        std::printf("  (the fast path against the exact path's golden image: `xval golden check %s` first)\n",
                    shellWord(file.string()).c_str());
    };
    if (const std::string problem = golden::goldenProblem(folder, m, file, renderers::goldenUpdateCommand(file, m.renderer)); !problem.empty()) {
      fail(problem);
      continue;
    }
    const golden::Entry& e = m.entries.at(file.stem().string());
    const fs::path work = scratch.dir() / ("work-" + attemptToken());
    fs::create_directories(work);
    Render fresh = renderForGolden(r, scene, work, request.timeout_seconds, precision);
    // The fast path is compared with the exact path's image: the settings
    // must agree on everything else.
    nlohmann::json compared = fresh.settings;
    if (precision == Precision::Float && e.settings.contains("precision")) compared["precision"] = e.settings["precision"];
    if (const std::string h = golden::settingsHash(compared); h != e.settings_sha256) {
      fail("rendered with other settings (" + fresh.settings.dump() + ") than the golden image (" +
           e.settings.dump() + ")");
      continue;
    }
    const Image stored = readImage(folder / e.image, scene.camera.width, scene.camera.height);
    std::string reason;
    const Tolerance tol = table.lookup(scene, set_id, &reason);
    // Stored and fresh images are the same renderer's, each within its
    // precision of the exact value; the reference renderer's fast path
    // (--precision float) computes in float32 throughout, as the default
    // model of a float32 renderer declares.
    const PrecisionModel& p = renderers::precisionOf(r);
    const PrecisionModel fresh_p = precision == Precision::Float ? float32Precision() : p;
    const PairMeasures measures = measurePair(stored, fresh.image, tol, {p, fresh_p});
    const CompareMetrics& cm = measures.compare;
    const bool pass = passes(measures, tol);
    const std::string figures =
        "max " + std::to_string(cm.max_abs * 65535.0) + "/65535 at (" + std::to_string(cm.worst_x) + "," +
        std::to_string(cm.worst_y) + "), " + std::to_string(cm.fraction_within * 100.0) + "% within " +
        std::to_string(tol.max_abs * 65535.0) + "/65535 (need " + std::to_string(tol.fraction * 100.0) +
        "%), mask disagreements no edge explains " + std::to_string(cm.mask_disagree - cm.mask_disagree_explained) +
        (tol.metrics.empty() ? "" : ", " + metricValuesText(measures) + " (declared: " + metricCriteriaText(tol.metrics) + ")") +
        (reason.empty() ? "" : "; declared: " + reason);
    if (pass)
      std::printf("pass %s (%s): %s\n", file.string().c_str(), request.precision.c_str(), figures.c_str());
    else {
      const std::string why = failedText(failedCriteria(measures, tol));
      fail("outside the tolerance against " + (folder / e.image).string() + " (stored " + e.date_utc + ", " +
           e.git_commit + "): " + why + "; " + figures);
    }
  }
  std::printf("%zu of %zu scenes match their golden images of %s\n", files.size() - size_t(failed), files.size(),
              r.display_name.c_str());
  return failed ? 1 : 0;
}

}  // namespace xval::validation
