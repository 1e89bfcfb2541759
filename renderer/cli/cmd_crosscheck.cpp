// xval crosscheck SCENE.json --renderer povray -o DIR [--tolerances FILE] [--junit FILE]: argument
// parsing; the work is validation::crosscheck (validate/validation/crosscheck.h).
//
// Validate of one scene with the reference renderer and one other
// (validate/validation/crosscheck.h): compares them with the declared tolerance, and
// writes validate's files to DIR (the renders in DIR/<scene>/,
// results.json, report.html) and DIR/metrics.json, the pair's verdict and
// metrics; with --junit, the verdict as JUnit XML (validate/report/junit_report.h),
// an error as <error>.
// Exit 0: within tolerance, or not expressible (the renderer declares it
// cannot express the scene; metrics.json says why); 1: outside; 2: an error
// (bad scene, renderer missing, failing or timing out: never a pass).
#include <cstdio>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "files/atomic_write.h"
#include "cli/renderer_file_option.h"
#include "renderers/registry.h"
#include "validate/validation/crosscheck.h"
#include "validate/report/junit_report.h"
#include "validate/tolerances.h"

namespace xval::cli {

void addCrosscheckCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string scene, renderer, dir, tolerances, junit;
    double timeout = kDefaultToolTimeoutSeconds;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "crosscheck",
      "Render a scene with the reference renderer and an external one, and compare them with "
      "the tolerance declared for that case: `xval validate` of that scene with those two renderers (its "
      "files in the output folder), and metrics.json, the pair's verdict and metrics.\nExit 0 within tolerance or when the renderer declares it cannot "
      "express the scene (NOT EXPRESSIBLE, the reason in metrics.json), 1 outside, 2 on an error "
      "(a missing, failing or hanging renderer is an error, never a pass).");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  const renderers::Registry& registry = renderers::registry();
  const std::vector<std::string> compared = registry.comparedIds();
  args->renderer = compared.front();
  std::string choices;
  for (const std::string& id : compared) choices += "\n  " + id + ": " + registry.at(id).summary;
  cmd->add_option("--renderer", args->renderer,
                  "The renderer compared with the reference (default " + compared.front() +
                      "; xval renderers lists them):" + choices);
  auto renderer_files = addRendererFileOption(cmd);
  cmd->add_option("-o,--output", args->dir, "Output folder")->required();
  cmd->add_option("--tolerances", args->tolerances, kToleranceFileHelp);
  cmd->add_option("--junit", args->junit,
                  "Also write the verdict as JUnit XML to this file (one testcase: classname = the "
                  "scene, name = the pair; outside the tolerance a <failure>, an error an <error>)");
  cmd->add_option("--timeout", args->timeout, "Seconds before the external renderer is killed")
      ->check(Seconds);
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, renderer_files, &run]() {
    run = [args, renderer_files]() -> int {
      const validation::CrosscheckRequest request{args->scene,   args->renderer,      args->dir,
                                                  args->tolerances, args->timeout,    args->budget.get(),
                                                  *renderer_files};
      int status = 2;
      results::Results results;
      try {
        status = validation::crosscheck(request, results);
      } catch (const std::exception& e) {
        results = validation::crosscheckError(request, e.what());
        std::fprintf(stderr, "xval crosscheck: error: %s\n", e.what());
      }
      if (!args->junit.empty()) {
        try {
          writeFileAtomically(args->junit, junitXml(results, "xval crosscheck"));
        } catch (const std::exception& e) {
          std::fprintf(stderr, "xval crosscheck: error: --junit %s: %s\n", args->junit.c_str(), e.what());
          return 2;
        }
      }
      return status;
    };
  });
}

}  // namespace xval::cli
