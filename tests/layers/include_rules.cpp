#include "include_rules.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <sstream>
#include <utility>

namespace vem::layers {

namespace {

constexpr std::string_view kTable = "tests/layers/allowed_includes.txt";

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> words(std::string_view text) {
  std::istringstream in{std::string(text)};
  std::vector<std::string> result;
  for (std::string word; in >> word;) result.push_back(word);
  return result;
}

std::string lineProblem(std::size_t number, std::string_view expected) {
  return std::string(kTable) + ": line " + std::to_string(number) + ": expected " +
         std::string(expected);
}

// "known FILE -> HEADER : REASON"
std::expected<KnownViolation, std::string> parseKnown(std::string_view rest, std::size_t number) {
  const auto arrow = rest.find("->");
  const auto colon = rest.find(" : ");
  const auto expected = "\"known FILE -> HEADER : REASON\"";
  if (arrow == std::string_view::npos || colon == std::string_view::npos || colon < arrow) {
    return std::unexpected(lineProblem(number, expected));
  }
  KnownViolation known{std::string(trim(rest.substr(0, arrow))),
                       std::string(trim(rest.substr(arrow + 2, colon - arrow - 2))),
                       std::string(trim(rest.substr(colon + 3)))};
  if (known.file.empty() || known.included.empty() || known.reason.empty()) {
    return std::unexpected(lineProblem(number, expected));
  }
  return known;
}

// "[tool] FOLDER -> FOLDER ..." into `rules`.
std::expected<void, std::string> parseFolderLine(std::string_view line, std::size_t number,
                                                 LayerRules& rules) {
  const auto arrow = line.find("->");
  const auto expected = "\"FOLDER -> FOLDER ...\" or \"tool FOLDER -> FOLDER ...\"";
  if (arrow == std::string_view::npos) return std::unexpected(lineProblem(number, expected));
  std::vector<std::string> left = words(line.substr(0, arrow));
  const bool tool = left.size() == 2 && left[0] == "tool";
  if (left.size() != 1 && !tool) return std::unexpected(lineProblem(number, expected));
  const std::string folder = left.back();
  if (rules.mayInclude.contains(folder)) {
    return std::unexpected(lineProblem(number, "each folder once, found " + folder + " again"));
  }
  rules.mayInclude[folder] = words(line.substr(arrow + 2));
  if (tool) rules.tools.insert(folder);
  return {};
}

std::string violationMessage(ViolationKind kind, const IncludeEdge& edge, const std::string& from,
                             const std::string& to) {
  const std::string head = edge.file + " includes " + edge.included + ", ";
  const std::string table = std::string(kTable);
  switch (kind) {
    case ViolationKind::Upward:
      return head + "an upward include: " + to + " sits above " + from +
             ", and a folder includes only the folders below it (" + table + ")";
    case ViolationKind::Sideways:
      return head + "a sideways include: neither of " + from + " and " + to +
             " is below the other, and a folder includes only the folders below it (" + table + ")";
    case ViolationKind::ToolFolder:
      return head + "from a tool's folder: nothing outside " + to +
             " may include it (move what is shared into a library below)";
    case ViolationKind::DetailHeader:
      return head + "a detail header of " + to + ": only " + to +
             " itself may include it (use its public interface)";
    case ViolationKind::UnknownFolder:
      return head + "but " + from + " is not in the layer table (add the folder to " + table +
             " in its layer)";
    case ViolationKind::StaleKnown: break;
  }
  return head + "which breaks the layer rules (" + table + ")";
}

const KnownViolation* knownFor(const LayerRules& rules, const IncludeEdge& edge) {
  for (const KnownViolation& known : rules.known) {
    if (known.file == edge.file && known.included == edge.included) return &known;
  }
  return nullptr;
}

std::optional<ViolationKind> kindOf(const LayerRules& rules, const IncludeEdge& edge,
                                    const std::set<std::string>& detailHeaders,
                                    std::string& unknownFolder) {
  const std::string from = folderOf(edge.file);
  const std::string to = folderOf(edge.included);
  if (from == to) return std::nullopt;
  for (const std::string& folder : {from, to}) {
    if (!rules.mayInclude.contains(folder)) {
      unknownFolder = folder;
      return ViolationKind::UnknownFolder;
    }
  }
  if (rules.tools.contains(to)) return ViolationKind::ToolFolder;
  if (detailHeaders.contains(edge.included)) return ViolationKind::DetailHeader;
  if (mayInclude(rules, from, to)) return std::nullopt;
  return mayInclude(rules, to, from) ? ViolationKind::Upward : ViolationKind::Sideways;
}

}  // namespace

std::string folderOf(std::string_view path) {
  const auto slash = path.rfind('/');
  return slash == std::string_view::npos ? std::string() : std::string(path.substr(0, slash));
}

std::expected<LayerRules, std::string> parseLayerRules(std::string_view text) {
  LayerRules rules;
  std::size_t number = 0;
  for (std::size_t start = 0; start <= text.size(); ++number) {
    const auto end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    line = trim(line);
    if (line.empty()) continue;
    if (line.starts_with("known ")) {
      auto known = parseKnown(line.substr(6), number + 1);
      if (!known) return std::unexpected(known.error());
      rules.known.push_back(std::move(*known));
    } else if (auto parsed = parseFolderLine(line, number + 1, rules); !parsed) {
      return std::unexpected(parsed.error());
    }
  }
  return rules;
}

bool mayInclude(const LayerRules& rules, const std::string& from, const std::string& to) {
  std::set<std::string> seen;
  std::vector<std::string> pending{from};
  while (!pending.empty()) {
    const std::string folder = std::move(pending.back());
    pending.pop_back();
    if (!seen.insert(folder).second) continue;
    const auto listed = rules.mayInclude.find(folder);
    if (listed == rules.mayInclude.end()) continue;
    for (const std::string& below : listed->second) {
      if (below == to) return true;
      pending.push_back(below);
    }
  }
  return false;
}

std::vector<Violation> findViolations(const std::vector<IncludeEdge>& includes,
                                      const LayerRules& rules,
                                      const std::set<std::string>& detailHeaders) {
  std::vector<Violation> violations;
  std::set<const KnownViolation*> seenKnown;
  for (const IncludeEdge& edge : includes) {
    if (const KnownViolation* known = knownFor(rules, edge)) {
      seenKnown.insert(known);
      continue;
    }
    std::string unknownFolder;
    const auto kind = kindOf(rules, edge, detailHeaders, unknownFolder);
    if (!kind) continue;
    const std::string from =
        *kind == ViolationKind::UnknownFolder ? unknownFolder : folderOf(edge.file);
    const std::string to =
        *kind == ViolationKind::UnknownFolder ? std::string() : folderOf(edge.included);
    violations.push_back(
        {*kind, edge.file, edge.included, violationMessage(*kind, edge, from, to)});
  }
  for (const KnownViolation& known : rules.known) {
    if (seenKnown.contains(&known)) continue;
    violations.push_back({ViolationKind::StaleKnown, known.file, known.included,
                          known.file + " no longer includes " + known.included +
                              ", listed as a known violation (" + known.reason +
                              "): remove its line from " + std::string(kTable)});
  }
  return violations;
}

std::optional<std::vector<std::string>> findCycle(const LayerRules& rules) {
  enum class Mark { Unseen, Open, Done };
  std::map<std::string, Mark> marks;
  std::vector<std::string> path;
  std::function<std::optional<std::vector<std::string>>(const std::string&)> visit =
      [&](const std::string& folder) -> std::optional<std::vector<std::string>> {
    Mark& mark = marks[folder];
    if (mark == Mark::Done) return std::nullopt;
    if (mark == Mark::Open) {
      std::vector<std::string> cycle(std::find(path.begin(), path.end(), folder), path.end());
      cycle.push_back(folder);
      return cycle;
    }
    mark = Mark::Open;
    path.push_back(folder);
    if (const auto listed = rules.mayInclude.find(folder); listed != rules.mayInclude.end()) {
      for (const std::string& below : listed->second) {
        if (auto cycle = visit(below)) return cycle;
      }
    }
    path.pop_back();
    marks[folder] = Mark::Done;
    return std::nullopt;
  };
  for (const auto& [folder, below] : rules.mayInclude) {
    if (auto cycle = visit(folder)) return cycle;
  }
  return std::nullopt;
}

std::optional<std::string> resolveInclude(const std::string& file, const std::string& spelled,
                                          const std::vector<std::string>& includeRoots,
                                          const std::set<std::string>& files) {
  const std::string beside = folderOf(file);
  std::vector<std::string> candidates{beside.empty() ? spelled : beside + "/" + spelled};
  for (const std::string& root : includeRoots) {
    candidates.push_back(root.empty() ? spelled : root + "/" + spelled);
  }
  for (const std::string& candidate : candidates) {
    const std::string normal = std::filesystem::path(candidate).lexically_normal().generic_string();
    if (files.contains(normal)) return normal;
  }
  return std::nullopt;
}

}  // namespace vem::layers
