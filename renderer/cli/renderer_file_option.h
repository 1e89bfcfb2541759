// --renderer-file FILE (repeatable) for the commands that take renderers:
// each file's renderer is added to the registry before the command runs
// (renderers/renderer_file.h). A --renderer option naming it is checked
// against the registry when the command runs, not when it is parsed.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "renderers/renderer_file.h"

namespace xval::cli {

inline std::shared_ptr<std::vector<std::string>> addRendererFileOption(CLI::App* cmd) {
  auto files = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--renderer-file", *files, renderers::kRendererFileHelp)->check(CLI::ExistingFile);
  return files;
}

}  // namespace xval::cli
