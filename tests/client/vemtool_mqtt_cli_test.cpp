// `vemtool subscribe mqtt://...` and `vemtool cameras` as a user meets them (the built executable
// against a real Mosquitto broker on 127.0.0.1, tests/support/mosquitto_broker.h, fed by the tests'
// own publisher): the JSON lines, the credentials and certificate options, and one sentence when
// they give up.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/stream_test_messages.h"
#include "support/test_mqtt_publisher.h"
#include "client/test_stream_server.h"
#include "support/command_run.h"
#include "support/mosquitto_broker.h"

namespace vem::client {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::bytesOf;
using test::lightFrameMessage;
using testing::TestMqttPublisher;
using vem::testing::CommandRun;
using vem::testing::MosquittoBroker;
using vem::testing::MosquittoBrokerConfig;

constexpr auto kWait = 20s;
constexpr const char* kLights = "vemcast/cam-1/lights";

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::unique_ptr<MosquittoBroker> startBroker(MosquittoBrokerConfig config = {}) {
  auto broker = MosquittoBroker::start(std::move(config));
  EXPECT_TRUE(broker.has_value()) << broker.error();
  return broker ? std::move(*broker) : nullptr;
}

stream::ServerMessage statusMessage(bool offline, const std::string& source) {
  stream::ServerMessage message;
  stream::Status& status = *message.mutable_status();
  status.set_source(source);
  status.set_state(offline ? stream::SOURCE_STATE_NO_DEVICE : stream::SOURCE_STATE_OK);
  status.set_frame_rate_hz(offline ? 0.0 : 30.0);
  status.set_light_count(64);
  status.set_offline(offline);
  status.set_publish_dropped(offline ? 0 : 3);
  return message;
}

class VemtoolMqttCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("vemtool_mqtt_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `vemtool ARGS` in the background, its output in `folder` (the test drives the broker
  // meanwhile).
  std::future<CommandRun> start(const std::string& args, const std::string& folder = "run") const {
    const fs::path out = dir_ / folder;
    fs::create_directories(out);
    return std::async(std::launch::async, [args, out] {
      return vem::testing::runCommand(vem::testing::commandLine(VEMTOOL_PATH, args), out);
    });
  }

  // A password file with `mode`, holding `password` and a newline.
  std::string passwordFile(const std::string& password, mode_t mode) const {
    const fs::path path = dir_ / "password";
    std::ofstream(path) << password << "\n";
    ::chmod(path.c_str(), mode);
    return path.string();
  }

  fs::path dir_;
};

// The JSON lines without the one field that depends on the moment of receipt.
std::vector<nlohmann::json> framesWithoutLatency(const std::string& out) {
  std::vector<nlohmann::json> frames;
  for (const std::string& line : linesOf(out)) {
    nlohmann::json frame = nlohmann::json::parse(line);
    EXPECT_TRUE(frame["latency_ms"].is_number()) << line;
    frame.erase("latency_ms");
    frames.push_back(std::move(frame));
  }
  return frames;
}

TEST_F(VemtoolMqttCli, SubscribePrintsTheSameJsonLinesOverMqttAsOverWebSocket) {
  const std::vector<std::uint64_t> seqs{1, 2, 4};
  test::TestStreamServer server(0);
  auto overWebSocket = start("subscribe " + server.url() + " --frames 3 --timeout 30", "ws");
  ASSERT_TRUE(server.waitForClientMessages(1, kWait));
  for (std::uint64_t seq : seqs) server.send(bytesOf(lightFrameMessage(seq, 2)));
  const CommandRun ws = overWebSocket.get();
  ASSERT_EQ(ws.exitCode, 0) << ws.err;

  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto overMqtt =
      start("subscribe " + broker->url("/vemcast/cam-1") + " --frames 3 --timeout 30", "mqtt");
  ASSERT_TRUE(broker->waitForLog(" 0 vemcast/cam-1/lights", kWait)) << broker->logText();
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  for (std::uint64_t seq : seqs) {
    ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(seq, 2)), true));
  }
  const CommandRun mqtt = overMqtt.get();
  ASSERT_EQ(mqtt.exitCode, 0) << mqtt.err;

  const auto wsFrames = framesWithoutLatency(ws.out);
  ASSERT_EQ(wsFrames.size(), 3U) << ws.out;
  EXPECT_EQ(framesWithoutLatency(mqtt.out), wsFrames) << mqtt.out;
  const auto stats = nlohmann::json::parse(linesOf(mqtt.err).back());
  EXPECT_EQ(stats["received"], 3);
  EXPECT_EQ(stats["skipped"], 1);
  EXPECT_EQ(stats["decode_errors"], 0);
}

TEST_F(VemtoolMqttCli, SubscribeWithAPrivatePasswordFileReachesABrokerThatNeedsOne) {
  MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"viewer", "s3cret"}, {"vemd", "other"}};
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port(), "vemd", "other");
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(9)), true));
  const std::string url =
      "mqtt://viewer@127.0.0.1:" + std::to_string(broker->port()) + "/vemcast/cam-1";
  const CommandRun r = start("subscribe " + url + " --password-file " +
                             passwordFile("s3cret", 0600) + " --frames 1 --timeout 30")
                           .get();
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto out = linesOf(r.out);
  ASSERT_EQ(out.size(), 1U) << r.out;
  EXPECT_EQ(nlohmann::json::parse(out[0])["seq"], 9);
}

TEST_F(VemtoolMqttCli, SubscribeRefusesAPasswordFileThatOthersCanReadNamingIt) {
  const std::string file = passwordFile("s3cret", 0644);
  const CommandRun r = start("subscribe mqtt://viewer@127.0.0.1:1/vemcast/cam-1 --password-file " +
                             file + " --frames 1")
                           .get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("vemtool: error: --password-file: " + file +
                       " can be read by group or others (mode 644); allow its owner only "
                       "(chmod 600)"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST_F(VemtoolMqttCli, SubscribeGivesUpWithTheBrokersReasonWhenItRefusesThePassword) {
  MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"viewer", "s3cret"}};
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  const CommandRun r =
      start("subscribe " + broker->url("/vemcast/cam-1") + " --username viewer --password-file " +
            passwordFile("wrong", 0600) + " --frames 1 --timeout 30")
          .get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("the broker 127.0.0.1:" + std::to_string(broker->port()) +
                       " refused the connection: not authorized"),
            std::string::npos)
      << r.err;
}

TEST_F(VemtoolMqttCli, SubscribeOverMqttsTrustsTheGivenCaFile) {
  MosquittoBrokerConfig config;
  config.tls = true;
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(5)), true));
  const CommandRun r = start("subscribe " + broker->tlsUrl("/vemcast/cam-1") + " --ca-file " +
                             broker->caFile().string() + " --frames 1 --timeout 30")
                           .get();
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(linesOf(r.out).at(0))["seq"], 5);
}

TEST_F(VemtoolMqttCli, SubscribeRefusesTheOtherTransportsOptionsAsAUsageError) {
  const CommandRun ws = start("subscribe ws://127.0.0.1:1/ --username viewer").get();
  EXPECT_EQ(ws.exitCode, 2);
  EXPECT_NE(ws.err.find("vemtool: error: --username, --password-file, --cert and --key are for "
                        "mqtt:// and mqtts:// addresses (see 'vemtool subscribe --help')"),
            std::string::npos)
      << ws.err;
  const CommandRun mqtt = start("subscribe mqtt://127.0.0.1:1/vemcast/cam-1 --token t").get();
  EXPECT_EQ(mqtt.exitCode, 2);
  EXPECT_NE(mqtt.err.find("--token and --token-file are for ws:// and wss:// addresses"),
            std::string::npos)
      << mqtt.err;
}

TEST_F(VemtoolMqttCli, CamerasListsEachCameraUnderThePrefixFromItsRetainedStatus) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish("vemcast/cam-b/status",
                            bytesOf(statusMessage(true, "v4l2:/dev/video0")), true));
  ASSERT_TRUE(
      vemd->publish("vemcast/cam-a/status", bytesOf(statusMessage(false, "synthetic:sky")), true));
  ASSERT_TRUE(
      vemd->publish("site/cam-x/status", bytesOf(statusMessage(false, "synthetic:sky")), true));
  const CommandRun r = start("cameras " + broker->url() + " --wait-ms 500").get();
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(linesOf(r.out),
            (std::vector<std::string>{
                "cam-a  online  synthetic:sky  ok  30.0 Hz  64 lights  3 dropped",
                "cam-b  offline  v4l2:/dev/video0  no device  0.0 Hz  64 lights  0 dropped"}))
      << r.out;

  const CommandRun json = start("cameras " + broker->url("/site") + " --wait-ms 500 --json").get();
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto lines = linesOf(json.out);
  ASSERT_EQ(lines.size(), 1U) << json.out;
  const auto camera = nlohmann::json::parse(lines[0]);
  EXPECT_EQ(camera["camera"], "cam-x");
  EXPECT_EQ(camera["online"], true);
  EXPECT_EQ(camera["source"], "synthetic:sky");
  EXPECT_EQ(camera["state"], "ok");
  EXPECT_EQ(camera["frame_rate_hz"], 30.0);
  EXPECT_EQ(camera["light_count"], 64);
  EXPECT_EQ(camera["publish_dropped"], 3);
}

TEST_F(VemtoolMqttCli, CamerasFailsWithOneSentenceNamingTheBrokerWhenNoneListens) {
  std::uint16_t port = 0;
  {
    auto broker = startBroker();
    ASSERT_NE(broker, nullptr);
    port = broker->port();
  }
  const CommandRun r = start("cameras mqtt://127.0.0.1:" + std::to_string(port)).get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(linesOf(r.err).back(), "vemtool: error: the connection to the broker 127.0.0.1:" +
                                       std::to_string(port) + " failed: Connection refused");
  EXPECT_TRUE(r.out.empty());
}

TEST_F(VemtoolMqttCli, CamerasRefusesACameraAddress) {
  const CommandRun r = start("cameras mqtt://127.0.0.1/vemcast/cam-1").get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("a broker's address names at most a prefix, no camera"), std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace vem::client
