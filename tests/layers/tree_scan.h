// The real tree for the layer check (include_rules.h): the project's source files under daemon/,
// calib/, client/ and proto/ (tests/ and build output are not scanned), their `#include "..."`
// lines resolved as the targets' include directories resolve them, the detail headers, and the
// allowed table's text. The thin shell around the pure check: reads files, decides nothing.
#pragma once

#include <expected>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "include_rules.h"

namespace vem::layers {

// Where `#include "..."` looks after the including file's folder: the project root and daemon/
// (target_include_directories of the project's targets).
inline const std::vector<std::string> kIncludeRoots{"", "daemon"};

struct SourceTree {
  std::set<std::string> files;          // .h and .cpp, relative to the root
  std::vector<IncludeEdge> includes;    // resolved to project files
  std::set<std::string> detailHeaders;  // open a `namespace ...::detail`, or sit in detail/
};

// Scans `root`; one sentence naming the file that cannot be read.
[[nodiscard]] std::expected<SourceTree, std::string> scanSourceTree(
    const std::filesystem::path& root);

[[nodiscard]] std::expected<std::string, std::string> readTextFile(
    const std::filesystem::path& path);

}  // namespace vem::layers
