// vemtool's subcommands. Each lives in its own <name>_command.cpp and registers itself on the
// top-level CLI11 app; its callback does the I/O and calls the pure core. A command reports bad
// input with one clear sentence on stderr and sets a non-zero exit code through `exitCode`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace vem::tool {

void addLightsCommand(CLI::App& app, int& exitCode);   // lights_command.cpp
void addFiltersCommand(CLI::App& app, int& exitCode);  // filters_command.cpp
void addCoherenceCommand(CLI::App& app, int& exitCode);  // coherence_command.cpp
void addInfoCommand(CLI::App& app, int& exitCode);     // info_command.cpp
void addRecoverCommand(CLI::App& app, int& exitCode);  // recover_command.cpp
void addSynthCommand(CLI::App& app, int& exitCode);    // synth_command.cpp
void addExportCommand(CLI::App& app, int& exitCode);   // export_command.cpp
void addImportCommand(CLI::App& app, int& exitCode);   // import_command.cpp
void addSubscribeCommand(CLI::App& app, int& exitCode);  // subscribe_command.cpp
void addCamerasCommand(CLI::App& app, int& exitCode);    // cameras_command.cpp

// Logs `message` (one sentence) as an error and returns the failure exit status (main.cpp).
[[nodiscard]] int fail(const std::string& message);

}  // namespace vem::tool
