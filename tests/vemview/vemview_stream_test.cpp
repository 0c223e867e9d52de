// vemview against the real vemd on 127.0.0.1: the lights it draws come from the stream (a moving
// synthetic sun), each new light frame is drawn with its shadow maps redrawn, and a glossy scene
// subscribes to the cube maps while a Lambertian one does not.
#include <chrono>
#include <expected>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "calib/core/plate_camera.h"
#include "calib/io/plate_camera_file.h"

#include "stream_e2e/small_camera.h"
#include "stream_e2e/vemd_process.h"
#include "support/command_run.h"
#include "support/mosquitto_broker.h"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using vem::testing::CommandRun;
using vem::testing::runCommand;

// vemd in `dir` (a small camera, a 256 x 64 map, 64 lights) on a synthetic sky, streaming on a
// free loopback port, with `pace` (--rate, --frames) added and `moreToml` after its configuration.
std::expected<std::unique_ptr<vem::e2e::VemdProcess>, std::string> spawnVemd(
    const fs::path& dir, const std::vector<std::string>& pace, const std::string& moreToml = "") {
  std::ofstream(dir / "camera.toml") << vem::e2e::smallCameraToml();
  std::ofstream(dir / "vemd.toml") << "version = 1\n[source]\ncamera = \""
                                   << (dir / "camera.toml").string()
                                   << "\"\n[processing]\nmap_width = 256\nmap_height = 64\n"
                                      "lights = 64\n"
                                   << moreToml;
  std::vector<std::string> args{"--config",       (dir / "vemd.toml").string(),
                                "--source",       "synthetic:sky",
                                "--stats-every",  "0",
                                "--stream-listen", "127.0.0.1:0"};
  args.insert(args.end(), pace.begin(), pace.end());
  return vem::e2e::VemdProcess::spawn(VEMD_PATH, args);
}

class VemviewStream : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vemview_stream_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    auto vemd = spawnVemd(dir_, {"--rate", "30"});
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

// The hard case "light frames that stop arriving": a composite paced by its plate keeps
// the last lights. vemd sends 4 light frames (2 a second) and stops; the plate has 30 pictures.
// Headless from a stream, each frame used to wait for new lights, and the run ended with "no new
// lights arrived" after the fourth; with --plate the plate's pictures pace it.
TEST(VemviewStreamPlate, LightsThatStopArrivingLeaveTheCompositeOnTheLastLights) {
  const fs::path dir = fs::temp_directory_path() /
                       ("vemview_stream_plate_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto vemd = spawnVemd(dir, {"--rate", "2", "--frames", "4"});
  ASSERT_TRUE(vemd.has_value()) << vemd.error();
  const auto port = (*vemd)->waitForPort(20s);
  ASSERT_TRUE(port.has_value()) << (*vemd)->stderrText();
  // A plate of 30 grey pictures, 64 x 48, and a camera looking at the origin from 2 m.
  {
    cv::VideoWriter writer((dir / "plate.mp4").string(), cv::CAP_FFMPEG,
                           cv::VideoWriter::fourcc('m', 'p', '4', 'v'), 30.0, cv::Size(64, 48));
    ASSERT_TRUE(writer.isOpened());
    for (int i = 0; i < 30; ++i) writer.write(cv::Mat(48, 64, CV_8UC3, cv::Scalar(90, 100, 110)));
  }
  vem::calib::PlateCamera camera;
  camera.camera.sensorWidthPx = 64;
  camera.camera.sensorHeightPx = 48;
  camera.camera.pixelFormat = vem::PixelFormat{3, 8};
  camera.intrinsics = {64, 48, 60.0, 60.0, 31.5, 23.5, vem::calib::PlateLensModel::BrownConrady, {}};
  camera.pose = vem::calib::plateLookingAt({0.0, 1.0, 2.0}, {0.0, 0.2, 0.0});
  ASSERT_TRUE(vem::calib::io::savePlateCameraFile(camera, dir / "plate.toml").has_value());
  const CommandRun r = runCommand(
      vem::testing::commandLine(
          VEMVIEW_PATH, "--connect ws://127.0.0.1:" + std::to_string(*port) +
                            " --timeout 5 --headless --renderer embree --count 16 --width 64 "
                            "--plate " + (dir / "plate.mp4").string() + " --plate-camera " +
                            (dir / "plate.toml").string() + " --frames 40 --no-exr --out " +
                            (dir / "out").string()),
      dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("no new lights"), std::string::npos) << r.err;
  std::ifstream timing(dir / "out" / "timing.jsonl");
  int drawn = 0;
  std::set<std::uint64_t> seqs;
  for (std::string line; std::getline(timing, line);) {
    const auto json = nlohmann::json::parse(line);
    drawn += json["drawn"].get<bool>() ? 1 : 0;
    seqs.insert(json["input_seq"].get<std::uint64_t>());
  }
  EXPECT_EQ(drawn, 30) << r.err;  // every picture, composited with the lights it had
  EXPECT_LE(seqs.size(), 4U) << "vemd sent 4 light frames";
  vemd->reset();
  fs::remove_all(dir);
}

}  // namespace

// vemview through an MQTT broker (issue 22): the real vemd publishing to a real Mosquitto with the
// shipped ACLs, vemview subscribing as the read-only viewer with its password file. Before the
// MQTT transport, vemview refused mqtt:// addresses.
TEST(VemviewMqtt, LightsThroughABrokerAsAReadOnlyViewerAreDrawnFrameByFrame) {
  const fs::path dir = fs::temp_directory_path() / ("vemview_mqtt_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  vem::testing::MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"vemd", "vemd-secret-2"}, {"viewer", "viewer-secret-2"}};
  config.acl = vem::testing::readTextFile(fs::path(VEM_SOURCE_DIR) / "config" / "mosquitto" /
                                          "vemcast.acl");
  auto broker = vem::testing::MosquittoBroker::start(config);
  ASSERT_TRUE(broker.has_value()) << broker.error();
  std::ofstream(dir / "vemd-credentials.toml")
      << "username = \"vemd\"\npassword = \"vemd-secret-2\"\n";
  std::ofstream(dir / "viewer.pass") << "viewer-secret-2\n";
  for (const char* secret : {"vemd-credentials.toml", "viewer.pass"}) {
    fs::permissions(dir / secret, fs::perms::owner_read | fs::perms::owner_write);
  }
  auto vemd = spawnVemd(dir, {"--rate", "30", "--mqtt", (*broker)->url("/vemcast/cam1")},
                        "[mqtt]\ncredentials_file = \"" +
                            (dir / "vemd-credentials.toml").string() + "\"\n");
  ASSERT_TRUE(vemd.has_value()) << vemd.error();
  ASSERT_TRUE((*vemd)->waitForStderr("mqtt: connected", 20s)) << (*vemd)->stderrText();

  const std::string url = "mqtt://viewer@127.0.0.1:" + std::to_string((*broker)->port()) +
                          "/vemcast/cam1";
  const CommandRun r = runCommand(
      vem::testing::commandLine(
          VEMVIEW_PATH, "--connect " + url + " --password-file " + (dir / "viewer.pass").string() +
                            " --headless --width 64 --height 48 --scene spheres --count 32 "
                            "--shadowed 8 --cluster 0 --frames 4 --out " + (dir / "out").string()),
      dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("stream mqtt://viewer@127.0.0.1"), std::string::npos) << r.err;
  std::ifstream timing(dir / "out" / "timing.jsonl");
  std::set<std::uint64_t> seqs;
  for (std::string line; std::getline(timing, line);) {
    seqs.insert(nlohmann::json::parse(line)["input_seq"].get<std::uint64_t>());
  }
  EXPECT_EQ(seqs.size(), 4U) << "each frame drawn from a new light frame through the broker";

  // MQTT-only options with a WebSocket address are a usage error in one sentence.
  const CommandRun wrong = runCommand(
      vem::testing::commandLine(VEMVIEW_PATH,
                                "--connect ws://127.0.0.1:1 --username viewer --headless"),
      dir);
  EXPECT_EQ(wrong.exitCode, 2);
  EXPECT_NE(wrong.err.find("are for an MQTT broker"), std::string::npos) << wrong.err;
  vemd->reset();
  fs::remove_all(dir);
}
