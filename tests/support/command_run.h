// Running a built executable as a user would, for the CLI tests: one shell command line, its
// standard output and error captured in files of a scratch folder and read back whole.
//
// - The command line goes to /bin/sh (std::system), so quoting and redirections are the shell's;
//   the caller quotes paths that may hold spaces.
// - exitCode is the process's exit status, or -1 when it did not exit (killed by a signal).
// - The capture files are `dir`/stdout and `dir`/stderr, overwritten by each run.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <sys/wait.h>

namespace vem::testing {

struct CommandRun {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// The whole file as bytes ("" when it cannot be read).
inline std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `program` then `args`, separated by a space. Built by appending: GCC 12 reports a false
// -Warray-bounds on std::string(LITERAL) + "..." for some lengths of the literal, and the literal
// here is a build path, whose length depends on where the project was cloned.
inline std::string commandLine(std::string_view program, std::string_view args) {
  std::string line(program);
  line.append(" ").append(args);
  return line;
}

// Runs `commandLine` with its output captured in `dir`, which must exist.
inline CommandRun runCommand(const std::string& commandLine, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout", err = dir / "stderr";
  const std::string command = commandLine + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readTextFile(out), readTextFile(err)};
}

}  // namespace vem::testing
