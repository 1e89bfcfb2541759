// xval: the toolkit's command-line tool. One subcommand per file
// (cli/cmd_*.cpp); this file only wires them together.
//
// Exit status, the same for every subcommand (the --help footer says it):
// 0 success (for the comparing commands: within the tolerance);
// 1 a check failed (compare, crosscheck, validate: outside the tolerance;
// extremes: a NaN/Inf in the reference renderer); 2 an error (bad command
// line, bad scene, I/O error, a tool that failed).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "cli/commands.h"
#include "process/run_process.h"
#include "renderers/renderer.h"

int main(int argc, char** argv) {
  // Before any thread starts: an interrupt stops every tool xval started.
  xval::installInterruptHandler();
  CLI::App app{
      "xval: cross-validates lighting models between its reference renderer and others (POV-Ray, "
      "Blender Cycles and EEVEE, gl on OpenGL, stored golden images, renderers defined by a file; "
      "`xval renderers` lists them).\nScene files are JSON (docs/scene-format.md)."};
  const std::string exit_status =
      "Exit status (every subcommand): 0 success, or within the tolerance; 1 a check failed "
      "(compare, crosscheck, validate: outside the tolerance; extremes: a NaN/Inf in the reference "
      "renderer); 2 an error (bad command line, bad input, a tool that failed).";
  app.footer(exit_status);
  app.require_subcommand(1);
  app.set_version_flag("--version", xval::renderers::kXvalVersion);
  std::function<int()> run;
  xval::cli::addRenderCommand(app, run);
  xval::cli::addExportCommand(app, run);
  xval::cli::addCompareCommand(app, run);
  xval::cli::addCrosscheckCommand(app, run);
  xval::cli::addGenerateCommand(app, run);
  xval::cli::addValidateCommand(app, run);
  xval::cli::addReportCommand(app, run);
  xval::cli::addBenchCommand(app, run);
  xval::cli::addExtremesCommand(app, run);
  xval::cli::addTradeoffCommand(app, run);
  xval::cli::addRenderersCommand(app, run);
  xval::cli::addGoldenCommand(app, run);
  xval::cli::addPackCommand(app, run);
  xval::cli::addLintCommand(app, run);
  for (CLI::App* sub : app.get_subcommands({})) sub->footer(exit_status);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    return run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "xval: error: %s\n", e.what());
    return 2;
  }
}
