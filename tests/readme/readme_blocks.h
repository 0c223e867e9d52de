// The shell commands of a Markdown file's ```sh blocks, with the "## " heading each falls under:
// continuation lines joined, comments and blank lines dropped. Pure (text in, commands out).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vem::testing {

struct ShellCommand {
  std::string heading;  // the last "## " heading above the block ("" before the first)
  std::string text;     // one command line, as a shell reads it
};

std::vector<ShellCommand> shellCommands(std::string_view markdown);

// The command without a trailing "# comment" (a '#' after white space, outside quotes).
std::string withoutComment(std::string_view line);

}  // namespace vem::testing
