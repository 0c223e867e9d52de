// VemviewProcessTest: the fixture of the tests that run the built vemview (VEMVIEW_PATH) as a
// user would: a fresh temporary folder per test, removed after it, and run(prefix, args), which
// runs `PREFIX vemview ARGS` through the shell with stderr captured, returning the exit code (-1
// when a signal ended it) and stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace vem::testing {

struct ViewRun {
  int exitCode = -1;
  std::string err;
};

inline std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class VemviewProcessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("vemview_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  ViewRun run(const std::string& prefix, const std::string& args) const {
    const std::filesystem::path err = dir_ / "stderr";
    const std::string command =
        prefix + std::string(VEMVIEW_PATH) + " " + args + " 2>" + err.string();
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readTextFile(err)};
  }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace vem::testing
