// xval: the toolkit's command-line tool. One subcommand per file
// (cli/cmd_*.cpp); this file only wires them together.
//
// Exit status: 0 success; 2 bad command line; otherwise 1 when the command
// failed (bad scene, I/O error, ...), except for the comparing commands
// (compare, crosscheck, validate), where 1 means "outside the tolerance" and
// 2 means an error.
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
      "xval: cross-validates lighting models between a reference renderer, POV-Ray and "
      "Blender.\nScene files are JSON (docs/scene-format.md)."};
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
    return 1;
  }
}
