// vemview against the real vemd on 127.0.0.1: the lights it draws come from the stream (a moving
// synthetic sun), each new light frame is drawn with its shadow maps redrawn, and a glossy scene
// subscribes to the cube maps while a Lambertian one does not.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "stream_e2e/small_camera.h"
#include "stream_e2e/vemd_process.h"
#include "support/command_run.h"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using vem::testing::CommandRun;
using vem::testing::runCommand;

class VemviewStream : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vemview_stream_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "camera.toml") << vem::e2e::smallCameraToml();
    std::ofstream(dir_ / "vemd.toml")
        << "version = 1\n[source]\ncamera = \"" << (dir_ / "camera.toml").string()
        << "\"\n[processing]\nmap_width = 256\nmap_height = 64\nlights = 64\n";
    auto vemd = vem::e2e::VemdProcess::spawn(
        VEMD_PATH, {"--config", (dir_ / "vemd.toml").string(), "--source", "synthetic:sky",
                    "--rate", "30", "--stats-every", "0", "--stream-listen", "127.0.0.1:0"});
    ASSERT_TRUE(vemd.has_value()) << vemd.error();
    vemd_ = std::move(*vemd);
    const auto port = vemd_->waitForPort(20s);
    ASSERT_TRUE(port.has_value()) << vemd_->stderrText();
    url_ = "ws://127.0.0.1:" + std::to_string(*port);
  }
  void TearDown() override {
    vemd_.reset();
    fs::remove_all(dir_);
  }
  int runVemview(const std::string& args) {
    const CommandRun r =
        runCommand(vem::testing::commandLine(VEMVIEW_PATH, "--connect " + url_ + " " + args), dir_);
    err_ = r.err;
    return r.exitCode;
  }

  fs::path dir_;
  std::string url_;
  std::string err_;
  std::unique_ptr<vem::e2e::VemdProcess> vemd_;
};

TEST_F(VemviewStream, EachNewLightFrameFromVemdIsDrawnWithItsShadowMapsRedrawn) {
  ASSERT_EQ(runVemview("--headless --width 64 --height 48 --scene spheres --count 32 --shadowed 8 "
                       "--cluster 0 --frames 4 --out " +
                       (dir_ / "out").string()),
            0)
      << err_;
  EXPECT_NE(err_.find("stream ws://127.0.0.1"), std::string::npos) << err_;
  EXPECT_NE(err_.find("lights only"), std::string::npos) << err_;  // Lambertian: no cube maps
  std::ifstream timing(dir_ / "out" / "timing.jsonl");
  std::set<std::uint64_t> seqs;
  int lines = 0;
  for (std::string line; std::getline(timing, line); ++lines) {
    const auto json = nlohmann::json::parse(line);
    seqs.insert(json["input_seq"].get<std::uint64_t>());
    EXPECT_TRUE(json["drawn"].get<bool>());
    EXPECT_EQ(json["lights"].get<int>(), 32);
    EXPECT_EQ(json["shadow_maps_rendered"].get<int>(), 8);  // new lights, new shadow maps
  }
  EXPECT_EQ(lines, 4);
  EXPECT_EQ(seqs.size(), 4U) << "headless from a stream, every frame is a new light frame";
}

TEST_F(VemviewStream, GlossySceneSubscribesToTheCubeMaps) {
  ASSERT_EQ(runVemview("--headless --width 64 --height 48 --scene default --count 32 --shadowed 8 "
                       "--frames 2 --out " +
                       (dir_ / "out").string()),
            0)
      << err_;
  EXPECT_NE(err_.find("lights and cube maps"), std::string::npos) << err_;
}

TEST_F(VemviewStream, UnreachableDaemonIsOneSentenceAfterTheTimeout) {
  // Port 1 on loopback: nothing listens, the client keeps retrying until the timeout.
  const CommandRun r =
      runCommand(vem::testing::commandLine(
                     VEMVIEW_PATH, "--connect ws://127.0.0.1:1 --headless --timeout 1 --frames 1"),
                 dir_);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("no lights arrived within 1 s"), std::string::npos) << r.err;
}

}  // namespace
