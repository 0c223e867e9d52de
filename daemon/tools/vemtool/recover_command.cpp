// `vemtool recover F.vem`: gives a truncated or damaged recording its trailing index again, by
// appending a new index and footer; no frame already in the file is moved or lost
// (docs/vem-format.md, "Recovery").
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "recording/recover_index.h"
#include "util/printable.h"

namespace vem::tool {
namespace {

int runRecover(const std::string& input) {
  auto report = recording::recoverIndex(input);
  const std::string name = util::printable(input);
  if (!report) {
    spdlog::error("{}", report.error().message);
    return EXIT_FAILURE;
  }
  const recording::DamageStats& d = report->damage;
  if (report->appendedBytes == 0) {
    std::cout << fmt::format("{}: the index is already valid ({} frames); nothing was written\n",
                             name, report->framesIndexed);
  } else {
    std::cout << fmt::format(
        "{}: the index was {}; appended a new index of {} frames ({} bytes); skipped {} damaged "
        "records ({} bytes) and a truncated tail of {} bytes\n",
        name, recording::indexStateName(report->indexBefore), report->framesIndexed,
        report->appendedBytes, d.damagedRecords, d.damagedBytes, d.truncatedTailBytes);
  }
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addRecoverCommand(CLI::App& app, int& exitCode) {
  auto input = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "recover", "Rebuild the trailing index of a truncated or damaged VEM recording");
  cmd->footer(
      "Example:\n  vemtool recover session.vem\n"
      "Appends a new index and footer listing every intact frame; nothing already in the file is\n"
      "rewritten. A file whose index is valid is left untouched.");
  cmd->add_option("file", *input, "The recording (.vem)")->required();
  cmd->callback([input, &exitCode] { exitCode = runRecover(*input); });
}

}  // namespace vem::tool
