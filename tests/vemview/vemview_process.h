// VemviewProcessTest: the fixture of the tests that run the built vemview (VEMVIEW_PATH) as a
// user would: a fresh temporary folder per test, removed after it, and run(prefix, args), which
// runs `PREFIX vemview ARGS` through the shell with stdout and stderr captured in that folder
// (support/command_run.h: the exit code, -1 when a signal ended it, and both outputs).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/command_run.h"

namespace vem::testing {

class VemviewProcessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("vemview_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  CommandRun run(const std::string& prefix, const std::string& args) const {
    return runCommand(prefix + vem::testing::commandLine(VEMVIEW_PATH, args), dir_);
  }
  [[nodiscard]] std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace vem::testing
