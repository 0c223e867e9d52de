// The command-line conventions every vemcast tool follows (vemd, vemtool, vemview, vemcalib):
// - exit status: 0 success, 1 a failure at run time, 2 a usage error (an unknown flag, a bad value);
// - help that reads as plain text: choices as "a|b|c", defaults as "(default: X)", a flag's negation
//   without CLI11's "{false}", and the exit statuses at the end of every page;
// - one error line: "TOOL: error: WHAT (see 'TOOL SUB --help')".
// A thin layer over CLI11 (libcli11-dev); the tools call applyConventions() once every option and
// subcommand is added, and exitStatusFor() when parsing throws.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace vem::cli {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;  // the tool ran and could not do its job
inline constexpr int kExitUsage = 2;    // the command line was wrong; nothing was done

// The line that ends every help page.
inline constexpr std::string_view kExitStatusHelp =
    "Exit status: 0 success, 1 failure at run time, 2 usage error (bad flag or value).";

// A parser type name with its validators ("ENUM:value in {gl->0,embree->1} OR {0,1}") as the
// plain text a person reads ("gl|embree"); a name without a choice list comes back unchanged.
std::string plainTypeName(std::string_view cli11TypeName);

// Sets the help formatter, the footer line and the failure message on app and every subcommand
// it has now. toolName is the executable's name ("vemtool").
void applyConventions(CLI::App& app, std::string_view toolName);

// Prints what CLI11 prints for the error (help or version on out, the error line on err) and gives
// the exit status: 0 for --help and --version, kExitUsage for anything else.
int exitStatusFor(const CLI::App& app, const CLI::ParseError& e, std::ostream& out, std::ostream& err);
int exitStatusFor(const CLI::App& app, const CLI::ParseError& e);

}  // namespace vem::cli
