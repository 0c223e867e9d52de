// The layer rules and their check (docs/architecture.md, "Layers"): which project folder may
// include which, read from tests/layers/allowed_includes.txt, and the pure check of a tree's
// includes against them. No files here: tree_scan.h reads the tree and the table.
//
// Paths are relative to the project root with '/' separators ("daemon/stream/stream_control.h");
// a file's folder is the path up to its last '/'. The rules are transitive: a folder may include
// the folders it lists and everything those may include.
#pragma once

#include <expected>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace vem::layers {

// One `#include "..."` of a project file, resolved to the project file it names.
struct IncludeEdge {
  std::string file;
  std::string included;
};

// A violation waiting for its fix, listed in the table with why.
struct KnownViolation {
  std::string file;
  std::string included;
  std::string reason;
};

struct LayerRules {
  std::map<std::string, std::vector<std::string>> mayInclude;  // folder -> the folders it lists
  std::set<std::string> tools;                                 // tools' folders
  std::vector<KnownViolation> known;
};

enum class ViolationKind { Upward, Sideways, ToolFolder, DetailHeader, UnknownFolder, StaleKnown };

struct Violation {
  ViolationKind kind = ViolationKind::Sideways;
  std::string file;
  std::string included;
  std::string message;  // one sentence naming the file, the include and the rule
};

// The table's text (allowed_includes.txt's format); one sentence naming the line when it is not.
[[nodiscard]] std::expected<LayerRules, std::string> parseLayerRules(std::string_view text);

// "daemon/stream" for "daemon/stream/stream_control.h"; "" for a file at the root.
[[nodiscard]] std::string folderOf(std::string_view path);

// Whether `from` may include `to`, directly or through the folders it lists.
[[nodiscard]] bool mayInclude(const LayerRules& rules, const std::string& from,
                              const std::string& to);

// Every include that breaks the rules (`detailHeaders`: the headers only their own folder may
// include), and every known violation that no longer occurs; in the order of `includes`.
[[nodiscard]] std::vector<Violation> findViolations(const std::vector<IncludeEdge>& includes,
                                                    const LayerRules& rules,
                                                    const std::set<std::string>& detailHeaders);

// A cycle of the table's folders ({"a", "b", "a"}), or nullopt when there is none.
[[nodiscard]] std::optional<std::vector<std::string>> findCycle(const LayerRules& rules);

// The project file that `#include "spelled"` in `file` names: beside `file` first (as the
// compiler looks), then under each of `includeRoots` ("" is the project root), among `files`;
// nullopt for a file outside the project (a generated or a system header).
[[nodiscard]] std::optional<std::string> resolveInclude(
    const std::string& file, const std::string& spelled,
    const std::vector<std::string>& includeRoots, const std::set<std::string>& files);

}  // namespace vem::layers
