// Option types for --help as a person reads them. CLI11 names an option's value by its C++ type and
// its validators ("INT:INT in [1 - 65536]", "TEXT:FILE"); these keep the check and let the value's
// name say what is expected ("1..65536", "FILE"); for vemtool and vemcalib. cli_conventions.h does the rest (choices,
// defaults, the exit statuses).
#pragma once

#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

namespace vem::help {

// The validator, checking as before, with no name in the help.
inline CLI::Validator quiet(CLI::Validator validator) {
  validator.description("");
  return validator;
}

// "MIN..MAX", the value's name for a CLI::Range(min, max).
template <class T>
std::string rangeName(T min, T max) {
  return fmt::format("{}..{}", min, max);
}

}  // namespace vem::help
