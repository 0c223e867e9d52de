#include "tree_scan.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>

namespace vem::layers {

namespace {

namespace fs = std::filesystem;

constexpr const char* kScannedFolders[] = {"daemon", "calib", "client", "proto"};

bool isSource(const fs::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".h" || extension == ".cpp";
}

// The quoted name of an `#include "..."` line, or nullopt.
std::optional<std::string> quotedInclude(std::string_view line) {
  const auto hash = line.find_first_not_of(" \t");
  if (hash == std::string_view::npos || line[hash] != '#') return std::nullopt;
  line.remove_prefix(hash + 1);
  line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
  if (!line.starts_with("include")) return std::nullopt;
  const auto open = line.find('"');
  const auto close = open == std::string_view::npos ? open : line.find('"', open + 1);
  if (close == std::string_view::npos) return std::nullopt;
  return std::string(line.substr(open + 1, close - open - 1));
}

bool opensDetailNamespace(std::string_view line) {
  if (!line.starts_with("namespace ")) return false;
  const auto brace = line.find('{');
  const std::string_view name =
      line.substr(10, brace == std::string_view::npos ? std::string_view::npos : brace - 10);
  return name.find("detail") != std::string_view::npos;
}

std::set<std::string> listSources(const fs::path& root) {
  std::set<std::string> files;
  for (const char* top : kScannedFolders) {
    if (!fs::is_directory(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (entry.is_regular_file() && isSource(entry.path())) {
        files.insert(entry.path().lexically_relative(root).generic_string());
      }
    }
  }
  return files;
}

}  // namespace

std::expected<std::string, std::string> readTextFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::unexpected(path.string() + ": cannot read it");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::expected<SourceTree, std::string> scanSourceTree(const fs::path& root) {
  SourceTree tree;
  tree.files = listSources(root);
  for (const std::string& file : tree.files) {
    auto text = readTextFile(root / file);
    if (!text) return std::unexpected(text.error());
    if (file.find("/detail/") != std::string::npos) tree.detailHeaders.insert(file);
    std::istringstream lines(*text);
    for (std::string line; std::getline(lines, line);) {
      if (file.ends_with(".h") && opensDetailNamespace(line)) tree.detailHeaders.insert(file);
      const auto spelled = quotedInclude(line);
      if (!spelled) continue;
      if (auto resolved = resolveInclude(file, *spelled, kIncludeRoots, tree.files)) {
        tree.includes.push_back({file, std::move(*resolved)});
      }
    }
  }
  return tree;
}

}  // namespace vem::layers
