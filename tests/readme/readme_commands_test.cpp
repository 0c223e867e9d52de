// The README's commands run as written (issue 17): every ```sh block of README.md, section by
// section, in a stand-in clone (a scratch folder with `build`, `config` and `cmake` linked to this
// checkout's, and `../shared` beside it), with vemd, vemtool, vemview and vemcalib on the PATH as
// an install puts them. Only the rewrites and skips listed below change what runs, each for its
// stated reason; a rule that no longer matches the README fails, so the list cannot go stale.
#include <sys/socket.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "readme/readme_blocks.h"
#include "support/command_run.h"

namespace vem::testing {
namespace {

namespace fs = std::filesystem;

// What a command becomes here, and why. `from` is a literal piece of README text.
struct Rewrite {
  const char* from;
  const char* to;
  const char* why;
};

constexpr Rewrite kRewrites[] = {
    {"bash cmake/deps.sh && cmake -S . -B build -G Ninja && cmake --build build --target vemd vemtool vemview && ",
     "", "the build that runs this test has installed the packages, configured and built"},
    {"--scene clouds --frames 300", "--scene clouds --frames 30",
     "a tenth of the frames: the same code path in a tenth of the time"},
    {"--frames 30 --orbit 3", "--frames 3 --orbit 3", "3 frames of the orbit show it turns"},
    {"--renderer reference --map ../shared/data/hdri/esplanade.exr --width 320 --height 240",
     "--renderer reference --map ../shared/data/hdri/esplanade.exr --width 80 --height 60 "
     "--reference-error 0.05",
     "the converged reference takes minutes; a small, looser one runs the same renderer"},
};

// Commands not run here, and why.
struct Skip {
  const char* command;
  const char* why;
};

constexpr Skip kSkips[] = {
    {"bash .ci/run", "the whole test suite, which is what runs this test"},
    {"cmake --install build",
     "it writes to /usr/local; the install test (install_puts_tools_on_path) installs the same rules "
     "into a staging folder and runs the installed tools"},
    {"cd build && cpack -G DEB && apt install ./vemcast_*.deb",
     "installing a package changes the machine; the package test (package_deb_holds_install) builds "
     "the .deb and inspects its files, conffiles and maintainer scripts"},
    {"cmake --build build --target render-bench",
     "the render study (tens of minutes); the bench and render-bench targets run it"},
};

// A window needs a display: Xvfb stands in, and a frame limit ends the window.
constexpr const char* kWindowWhy = "no display here: xvfb-run stands in, and --frames 2 closes the window";
// Tests run side by side, and two vemds cannot both stream on the default 127.0.0.1:8765.
constexpr const char* kOwnPortWhy =
    "tests run side by side: each vemd streams on a free port of its own, not the default 8765";
// Commands that talk to a running vemd get one, started by the test on a free loopback port.
constexpr const char* kStreamUrl = "ws://127.0.0.1:8765";

fs::path sourceDir() { return VEM_SOURCE_DIR; }

std::string readme() { return readTextFile(sourceDir() / "README.md"); }

bool contains(const std::string& s, std::string_view piece) { return s.find(piece) != std::string::npos; }

std::string replaceAll(std::string s, std::string_view from, std::string_view to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) {
    s.replace(at, from.size(), to);
  }
  return s;
}

int freeLoopbackPort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(fd);
  return ntohs(address.sin_port);
}

bool isAssignment(const std::string& command) {
  const auto equals = command.find('=');
  return equals != std::string::npos && command.find(' ') == std::string::npos && equals > 0;
}

// A stand-in clone: a scratch folder holding `vemcast/` (build, config, cmake linked to this
// checkout) beside `shared/` (linked to the shared data's folder), and `bin/` with the four tools.
struct StandInClone {
  fs::path root;
  fs::path clone;
  fs::path bin;

  explicit StandInClone(const std::string& name) {
    root = fs::temp_directory_path() / fmt::format("vem-readme-{}-{}", name, ::getpid());
    fs::remove_all(root);
    clone = root / "vemcast";
    bin = root / "bin";
    fs::create_directories(clone);
    fs::create_directories(bin);
    fs::create_directory_symlink(fs::path(VEM_SHARED_DATA_DIR).parent_path(), root / "shared");
    fs::create_directory_symlink(VEM_BINARY_DIR, clone / "build");
    for (const char* folder : {"config", "cmake", "docs"}) {
      fs::create_directory_symlink(sourceDir() / folder, clone / folder);
    }
    for (const char* tool : {VEMD_PATH, VEMTOOL_PATH, VEMVIEW_PATH, VEMCALIB_PATH}) {
      fs::create_symlink(tool, bin / fs::path(tool).filename());
    }
  }
  ~StandInClone() {
    if (!::testing::Test::HasFailure()) fs::remove_all(root);
  }
};

// Runs the section's commands in order; assignments (V=...) carry over to later commands.
void runSection(const std::string& heading, const std::string& name) {
  std::vector<ShellCommand> commands;
  for (ShellCommand& c : shellCommands(readme())) {
    if (c.heading == heading) commands.push_back(std::move(c));
  }
  ASSERT_FALSE(commands.empty()) << "README.md has no ```sh block under '## " << heading << "'";
  StandInClone here(name);
  std::string assignments;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const std::string& asWritten = commands[i].text;
    if (isAssignment(asWritten)) {
      assignments += asWritten + "\n";
      continue;
    }
    const Skip* skip = nullptr;
    for (const Skip& s : kSkips) {
      if (asWritten == s.command) skip = &s;
    }
    if (skip != nullptr) {
      std::cout << "skipped: " << asWritten << "\n  why: " << skip->why << "\n";
      continue;
    }
    std::string command = asWritten;
    for (const Rewrite& r : kRewrites) {
      if (contains(command, r.from)) {
        command = replaceAll(command, r.from, r.to);
        std::cout << "rewritten (" << r.why << ")\n";
      }
    }
    if (contains(command, "vemd --source")) {
      command = replaceAll(command, "vemd --source", "vemd --stream-listen 127.0.0.1:0 --source");
      std::cout << "rewritten (" << kOwnPortWhy << ")\n";
    }
    const bool tool = command.rfind("vemview ", 0) == 0 || command.rfind("$V ", 0) == 0;
    if (tool && !contains(command, "--headless")) {
      command = "xvfb-run -a " + command + (contains(command, "--frames") ? "" : " --frames 2");
      std::cout << "rewritten (" << kWindowWhy << ")\n";
    }
    std::string script = "set -e\ncd " + here.clone.string() + "\nexport PATH=" + here.bin.string() +
                         ":$PATH\n" + assignments;
    if (contains(command, kStreamUrl)) {
      const int port = freeLoopbackPort();
      command = replaceAll(command, kStreamUrl, fmt::format("ws://127.0.0.1:{}", port));
      script += fmt::format(
          "vemd --source synthetic:sky --stream-listen 127.0.0.1:{} >vemd-for-{}.log 2>&1 &\n"
          "server=$!\ntrap 'kill $server; wait $server || true' EXIT\n",
          port, i);
      std::cout << "with a vemd running (vemd --source synthetic:sky) on port " << port << "\n";
    }
    script += command + "\n";
    const fs::path scriptFile = here.root / fmt::format("command-{}.sh", i);
    std::ofstream(scriptFile) << script;
    const auto start = std::chrono::steady_clock::now();
    const CommandRun run = runCommand("bash " + scriptFile.string(), here.root);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << fmt::format("{:7.1f} s  $ {}\n", seconds, command);
    ASSERT_EQ(run.exitCode, 0) << "README command failed: " << asWritten << "\nran: " << command
                               << "\nstdout:\n" << run.out << "\nstderr:\n" << run.err;
  }
}

TEST(ReadmeCommands, TheMainJobRunsAsWrittenAfterTheBuild) {
  runSection("", "main");
}

TEST(ReadmeCommands, RunningTheDaemonRunsAsWritten) {
  runSection("Running the daemon", "daemon");
}

TEST(ReadmeCommands, RunningTheRenderClientRunsAsWritten) {
  runSection("Running the render client", "render");
}

TEST(ReadmeCommands, PuttingObjectsIntoACamerasViewRunsAsWritten) {
  runSection("Putting objects into a camera's view", "composite");
}

TEST(ReadmeCommands, InstallingIsLeftToTheInstallAndPackageTests) {
  runSection("Installing", "installing");
}

TEST(ReadmeCommands, TheCalibrationWalkThroughRunsAsWritten) {
  runSection("Calibrating a camera", "calibration");
}

// Every shell command sits under a section a test above runs; every rule still matches the README.
TEST(ReadmeCommands, EveryShellCommandIsRunOrSkippedForAStatedReason) {
  const std::vector<std::string> sections{"",
                                          "Installing",
                                          "Running the daemon",
                                          "Running the render client",
                                          "Putting objects into a camera's view",
                                          "Calibrating a camera"};
  const std::vector<ShellCommand> commands = shellCommands(readme());
  for (const ShellCommand& c : commands) {
    EXPECT_NE(std::find(sections.begin(), sections.end(), c.heading), sections.end())
        << "'" << c.text << "' under '## " << c.heading << "' is run by no test: add its section";
  }
  auto inReadme = [&](std::string_view piece, bool whole) {
    for (const ShellCommand& c : commands) {
      if (whole ? c.text == piece : contains(c.text, piece)) return true;
    }
    return false;
  };
  for (const Rewrite& r : kRewrites) EXPECT_TRUE(inReadme(r.from, false)) << "stale rewrite: " << r.from;
  for (const Skip& s : kSkips) EXPECT_TRUE(inReadme(s.command, true)) << "stale skip: " << s.command;
}

TEST(ReadmeBlocks, ContinuationLinesJoinAndCommentsGo) {
  const auto commands = shellCommands(
      "## A\n```sh\nX=1   # set\n# a whole comment line\nvemd --a \\\n   --b  # trailing\n```\n");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].text, "X=1");
  EXPECT_EQ(commands[1].text, "vemd --a --b");
  EXPECT_EQ(commands[1].heading, "A");
}

TEST(ReadmeBlocks, HashInsideQuotesOrAWordIsNotAComment) {
  EXPECT_EQ(withoutComment("echo '# kept' a#b  # gone"), "echo '# kept' a#b");
}

TEST(ReadmeBlocks, OtherFencesAreNotRunAndHeadingsInsideThemDoNotCount) {
  const auto commands = shellCommands("## A\n```text\n## not a heading\nvemtool MAP\n```\n```sh\nls\n```\n");
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].text, "ls");
  EXPECT_EQ(commands[0].heading, "A");
}

}  // namespace
}  // namespace vem::testing
