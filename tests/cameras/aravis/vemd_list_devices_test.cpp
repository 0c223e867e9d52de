// `vemd --list-devices` as a user runs it, inside the Aravis tests' network namespace (only
// loopback, run_in_netns.sh), with Aravis's fake GigE Vision camera serving on 127.0.0.1: the
// listing names the camera by the --source spec that opens it, its model, serial and modes, and
// still lists the other backends (here: none of theirs).
#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "aravis_test_rig.h"
#include "fake_gv_camera.h"

namespace vem::testing {
namespace {

struct CommandResult {
  int exitCode = -1;
  std::string out;
};

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

TEST(VemdListDevices, ListsTheFakeGigECameraWithItsSpecAndModesAndEveryBackend) {
  auto fake = FakeGvCamera::start("VEM12", writeFakeGenicam({"Mono8", "Mono16"}));
  ASSERT_TRUE(fake);
  const CommandResult listed = runCommand(std::string(VEMD_PATH) + " --list-devices 2>/dev/null");
  ASSERT_EQ(listed.exitCode, 0) << listed.out;
  EXPECT_NE(listed.out.find("aravis:Aravis-Fake-VEM12  Aravis Fake (VEM12)\n"), std::string::npos)
      << listed.out;
  EXPECT_NE(listed.out.find("    Mono16 2048x2048\n"), std::string::npos) << listed.out;
  // Every backend gets its say, whether or not it sees a camera.
  EXPECT_NE(listed.out.find("\nv4l2:"), std::string::npos) << listed.out;
  EXPECT_NE(listed.out.find("\nlibcamera:"), std::string::npos) << listed.out;
}

}  // namespace
}  // namespace vem::testing
