// The subcommands of xval. Each add*Command registers its options on `app`
// and sets `run` to its action when it is the subcommand chosen.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace xval::cli {

void addRenderCommand(CLI::App& app, std::function<int()>& run);
void addExportCommand(CLI::App& app, std::function<int()>& run);
void addCompareCommand(CLI::App& app, std::function<int()>& run);
void addCrosscheckCommand(CLI::App& app, std::function<int()>& run);
void addGenerateCommand(CLI::App& app, std::function<int()>& run);
void addValidateCommand(CLI::App& app, std::function<int()>& run);
void addReportCommand(CLI::App& app, std::function<int()>& run);
void addBenchCommand(CLI::App& app, std::function<int()>& run);
void addExtremesCommand(CLI::App& app, std::function<int()>& run);
void addTradeoffCommand(CLI::App& app, std::function<int()>& run);
void addRenderersCommand(CLI::App& app, std::function<int()>& run);
void addGoldenCommand(CLI::App& app, std::function<int()>& run);
void addPackCommand(CLI::App& app, std::function<int()>& run);
void addLintCommand(CLI::App& app, std::function<int()>& run);

}  // namespace xval::cli
