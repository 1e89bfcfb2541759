// xval compare A.exr B.exr [--tolerances FILE] [--tolerance-16bit T] [--fraction F] [--diff D.exr] [--json]
//
// The tolerance is the default of the tolerance file (validate/tolerances.h:
// --tolerances FILE, else the toolkit's own: compare has no scene), with
// --tolerance-16bit and --fraction replacing its fields.
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cli/commands.h"
#include "image/compare.h"
#include "renderers/registry.h"
#include "image/pair_failure.h"
#include "image/image_header.h"
#include "image/metric_criteria.h"
#include "image/metric_table.h"
#include "image/perceptual.h"
#include "validate/tolerances.h"

#include <nlohmann/json.hpp>

namespace xval::cli {

void addCompareCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string a, b, diff, tolerances, renderers;
    std::optional<double> tol16, fraction;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Compare two renders of one scene over the pixels both cover (alpha > 0): max abs, "
      "99.9th percentile, RMSE, PSNR, fraction within tolerance, hit-mask disagreements (on "
      "silhouettes or not).\nExit 0 when within tolerance, 1 when not, 2 on errors.");
  cmd->add_option("a", args->a, "First image")->required()->check(CLI::ExistingFile);
  cmd->add_option("b", args->b, "Second image")->required()->check(CLI::ExistingFile);
  cmd->add_option("--tolerances", args->tolerances,
                  "Tolerance file whose default is used (default: the toolkit's own "
                  "reference/tolerances.json; compare has no scene, so no search; the file used is printed)");
  cmd->add_option("--tolerance-16bit", args->tol16,
                  "Per-pixel tolerance in 1/65535 (default: the tolerance file's max_abs_16bit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--fraction", args->fraction,
                  "Fraction of covered pixels that must be within it (default: the tolerance file's fraction)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--renderers", args->renderers,
                  "A,B: the renderers that made a and b (ids of `xval renderers`): the comparison adds their "
                  "precision bounds (docs/precision-models.md) to what a's or b's diagnostics channels explain "
                  "(default: none, so only the tolerance, edges and backfacing normals explain a difference)");
  cmd->add_option("--diff", args->diff, "Write |a - b| to this image");
  cmd->add_flag("--json", args->json, "Print the metrics as JSON");
  cmd->callback([args, &run]() {
    run = [args]() -> int {
     try {
      // Both headers first: sizes that differ, or exceed the limit of images
      // read back (image/image.h), are refused before any pixel is allocated;
      // so is a file that is not a regular file (a FIFO would block).
      const ImageHeader ha = readImageHeader(args->a), hb = readImageHeader(args->b);
      if (ha.width != hb.width || ha.height != hb.height)
        throw std::runtime_error("cannot compare " + args->a + " (" + std::to_string(ha.width) + "x" +
                                 std::to_string(ha.height) + ") with " + args->b + " (" +
                                 std::to_string(hb.width) + "x" + std::to_string(hb.height) + ")");
      Image a = readImage(args->a), b = readImage(args->b, a.width, a.height);
      const ToleranceFile tol_file = findToleranceFile(args->tolerances, {});
      Tolerance t = loadTolerances(tol_file.path).default_tolerance;
      if (args->tol16) t.max_abs = *args->tol16 / 65535.0;
      if (args->fraction) t.fraction = *args->fraction;
      const std::string tol_source = args->tol16 && args->fraction
                                         ? std::string("from --tolerance-16bit and --fraction")
                                         : std::string(args->tol16 || args->fraction ? "the option given, the rest " : "") +
                                               "from the default of " + tol_file.describe();
      PairPrecision precision;
      if (!args->renderers.empty()) {
        const size_t comma = args->renderers.find(',');
        if (comma == std::string::npos || args->renderers.find(',', comma + 1) != std::string::npos)
          throw std::runtime_error("--renderers \"" + args->renderers +
                                   "\": expected two renderer ids separated by a comma, e.g. reference,gl");
        precision.a = renderers::precisionOf(renderers::registry().at(args->renderers.substr(0, comma)));
        precision.b = renderers::precisionOf(renderers::registry().at(args->renderers.substr(comma + 1)));
      }
      const PairMeasures measures = measurePair(a, b, t, precision);
      const CompareMetrics& m = measures.compare;
      if (a.has_alpha != b.has_alpha)
        std::fprintf(stderr,
                     "xval compare: note: %s has no alpha channel (an RGB image: xval's own PNGs are RGBA), so "
                     "every one of its pixels counts as covered and the %lld mask disagreements say nothing "
                     "about coverage; compare the EXRs (xval render -o OUT.exr) for the hit mask\n",
                     (a.has_alpha ? args->b : args->a).c_str(), m.mask_disagree);
      if (!args->diff.empty()) writeImage(differenceImage(a, b), args->diff, kDifferenceExrCompression);
      const PerceptualMetrics& pm = measures.perceptual;
      if (args->json) {
        nlohmann::json j = pairJson(measures, t);
        j["failed"] = failedJson(failedCriteria(measures, t));
        j["tolerance_source"] = tol_source;
        std::printf("%s\n", j.dump(2).c_str());
      } else {
        std::printf("tolerance: %.6g/65535 on %.6g%%%s, %s\n", t.max_abs * 65535.0, 100.0 * t.fraction,
                    t.metrics.empty() ? "" : (", " + metricCriteriaText(t.metrics)).c_str(), tol_source.c_str());
        std::printf("SSIM %.6f  CIEDE2000 mean %.4f max %.4f  YIQ delta mean %.3g max %.3g\n", pm.ssim,
                    pm.ciede2000_mean, pm.ciede2000_max, pm.yiq_mean, pm.yiq_max);
        std::printf("metrics: %s\n", metricValuesText(measures).c_str());
        std::printf(
            "covered %lld px, mask disagreements %lld (%lld explained by edges)\n"
            "max %.3f  p99.9 %.3f  RMSE %.4f (x/65535)  PSNR %.1f dB  within %.3g: %.5f%%  -> %s\n",
            m.covered_both, m.mask_disagree, m.mask_disagree_explained, m.max_abs * 65535,
            m.p999_abs * 65535, m.rmse * 65535, m.psnr_db, t.max_abs * 65535, 100 * m.fraction_within,
            passes(measures, t) ? "PASS" : "FAIL");
        std::printf("pixels by error (x/65535):");
        const char* names[7] = {"<=0.5", "<=1", "<=2", "<=4", "<=16", "<=256", ">256"};
        for (int i = 0; i < 7; ++i) std::printf(" %s:%lld", names[i], m.histogram[i]);
        std::printf("\nover tolerance: %lld (%s; largest precision bound %.3f)\n", m.over_tolerance,
                    classCountsText(m).c_str(), m.max_precision_bound * 65535);
        std::printf("max unexplained %.3f (x/65535) at (%d, %d), cap %.6g\n", m.max_unexplained * 65535,
                    m.worst_unexplained_x, m.worst_unexplained_y, t.max_unexplained * 65535);
        std::printf("worst pixel (%d, %d)\n", m.worst_x, m.worst_y);
        for (const PairFailure& f : failedCriteria(measures, t)) std::printf("fails: %s\n", f.text.c_str());
      }
      return passes(measures, t) ? 0 : 1;
     } catch (const std::exception& e) {
      std::fprintf(stderr, "xval compare: error: %s\n", e.what());
      return 2;
     }
    };
  });
}

}  // namespace xval::cli
