// xval report RESULTS.json [-o report.html] [--extremes DIR] [--tradeoff DIR]
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "validate/report/report.h"

namespace xval::cli {

void addReportCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string results, html, extremes, tradeoff;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write report.html (failures first; renders side by side, heat maps, metrics, verdicts, "
      "the paper's Figure 1 claims, a gnuplot summary plot) from a results.json of `xval validate` "
      "and the files it names (previews, heat maps, the extremes and trade-off folders); it "
      "regenerates only the summary plot and the heat-map scale.");
  cmd->add_option("results", args->results, "results.json")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->html, "Output HTML (default: report.html beside results.json)");
  cmd->add_option("--extremes", args->extremes,
                  "Show the extremes section of this folder (`xval extremes -o DIR`) instead of the one "
                  "results.json names")
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--tradeoff", args->tradeoff,
                  "Show the trade-off section of this folder (`xval tradeoff SCENE -o DIR`) instead of "
                  "the one results.json names")
      ->check(CLI::ExistingDirectory);
  cmd->callback([args, &run]() {
    run = [args]() {
      std::filesystem::path out = args->html.empty()
          ? std::filesystem::path(args->results).parent_path() / "report.html"
          : std::filesystem::path(args->html);
      ReportSections sections;
      if (!args->extremes.empty()) sections.extremes = args->extremes;
      if (!args->tradeoff.empty()) sections.tradeoff = args->tradeoff;
      writeReport(args->results, out, sections);
      std::fprintf(stderr, "xval report: wrote %s\n", out.c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
