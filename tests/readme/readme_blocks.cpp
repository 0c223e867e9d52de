#include "readme/readme_blocks.h"

#include <sstream>

namespace vem::testing {
namespace {

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

}  // namespace

std::string withoutComment(std::string_view line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      return trimmed(line.substr(0, i));
    }
  }
  return trimmed(line);
}

std::vector<ShellCommand> shellCommands(std::string_view markdown) {
  std::vector<ShellCommand> commands;
  std::istringstream in{std::string(markdown)};
  std::string line, heading, pending;
  bool inShell = false, inOtherFence = false;
  while (std::getline(in, line)) {
    if (!inShell && !inOtherFence && line.rfind("## ", 0) == 0) {
      heading = trimmed(std::string_view(line).substr(3));
      continue;
    }
    if (line.rfind("```", 0) == 0) {
      if (inShell || inOtherFence) {
        inShell = inOtherFence = false;
      } else {
        inShell = trimmed(std::string_view(line).substr(3)) == "sh";
        inOtherFence = !inShell;
      }
      continue;
    }
    if (!inShell) continue;
    std::string command = withoutComment(line);
    const bool continues = !command.empty() && command.back() == '\\';
    if (continues) command.pop_back();
    if (!pending.empty()) pending.push_back(' ');
    pending.append(trimmed(command));
    if (!continues && !pending.empty()) {
      commands.push_back({heading, pending});
      pending.clear();
    }
  }
  return commands;
}

}  // namespace vem::testing
