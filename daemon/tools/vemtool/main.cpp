// vemtool: lights from map files, and the tools around them. A thin shell over the core library:
// each subcommand (see commands.h) reads its input, calls the core, prints the result.
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "util/cli_conventions.h"

int vem::tool::fail(const std::string& message) {
  spdlog::error("{}", message);
  return vem::cli::kExitFailure;
}

int main(int argc, char** argv) {
  // Diagnostics go to stderr, one line each; stdout carries only results (JSON).
  auto logger = spdlog::stderr_color_st("vemtool");
  logger->set_pattern("vemtool: %^%l%$: %v");
  spdlog::set_default_logger(logger);

  CLI::App app{"vemtool: directional lights from HDR environment maps, and tools (vemcast)"};
  app.require_subcommand(1);
  int exitCode = vem::cli::kExitSuccess;
  vem::tool::addLightsCommand(app, exitCode);
  vem::tool::addFiltersCommand(app, exitCode);
  vem::tool::addCoherenceCommand(app, exitCode);
  vem::tool::addInfoCommand(app, exitCode);
  vem::tool::addRecoverCommand(app, exitCode);
  vem::tool::addSynthCommand(app, exitCode);
  vem::tool::addExportCommand(app, exitCode);
  vem::tool::addImportCommand(app, exitCode);
  vem::tool::addSubscribeCommand(app, exitCode);
  vem::tool::addCamerasCommand(app, exitCode);
  vem::cli::applyConventions(app, "vemtool");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return vem::cli::exitStatusFor(app, e);
  }
  return exitCode;
}
