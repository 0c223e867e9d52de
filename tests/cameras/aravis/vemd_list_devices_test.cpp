// `vemd --list-devices` as a user runs it, inside the Aravis tests' network namespace (only
// loopback, run_in_netns.sh), with Aravis's fake GigE Vision camera serving on 127.0.0.1: the
// listing names the camera by the --source spec that opens it, its model, serial and modes, and
// still lists the other backends (here: none of theirs).
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "aravis_test_rig.h"
#include "fake_gv_camera.h"
#include "support/command_run.h"

namespace vem::testing {
namespace {

TEST(VemdListDevices, ListsTheFakeGigECameraWithItsSpecAndModesAndEveryBackend) {
  auto fake = FakeGvCamera::start("VEM12", writeFakeGenicam({"Mono8", "Mono16"}));
  ASSERT_TRUE(fake);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vemd_list_devices_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CommandRun listed = runCommand(vem::testing::commandLine(VEMD_PATH, "--list-devices"), dir);
  std::filesystem::remove_all(dir);
  ASSERT_EQ(listed.exitCode, 0) << listed.out << listed.err;
  EXPECT_NE(listed.out.find("aravis:Aravis-Fake-VEM12  Aravis Fake (VEM12)\n"), std::string::npos)
      << listed.out;
  EXPECT_NE(listed.out.find("    Mono16 2048x2048\n"), std::string::npos) << listed.out;
  // Every backend gets its say, whether or not it sees a camera.
  EXPECT_NE(listed.out.find("\nv4l2:"), std::string::npos) << listed.out;
  EXPECT_NE(listed.out.find("\nlibcamera:"), std::string::npos) << listed.out;
}

}  // namespace
}  // namespace vem::testing
