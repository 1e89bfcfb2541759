// xval report RESULTS.json [-o report.html]
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "validate/report.h"

namespace xval::cli {

void addReportCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string results, html;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write report.html (failures first; renders side by side, heat maps, metrics, verdicts, "
      "a gnuplot summary plot) from a results.json of `xval validate` and the images beside it.");
  cmd->add_option("results", args->results, "results.json")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->html, "Output HTML (default: report.html beside results.json)");
  cmd->callback([args, &run]() {
    run = [args]() {
      std::filesystem::path out = args->html.empty()
          ? std::filesystem::path(args->results).parent_path() / "report.html"
          : std::filesystem::path(args->html);
      writeReport(args->results, out);
      std::fprintf(stderr, "xval report: wrote %s\n", out.c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
