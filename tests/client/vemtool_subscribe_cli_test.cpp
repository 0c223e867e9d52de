// `vemtool subscribe` as a user meets it (runs the built executable against the in-test server):
// the JSON lines it prints, the statistics line, and one sentence when it gives up.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/stream_test_messages.h"
#include "client/test_stream_server.h"
#include "support/command_run.h"

namespace vem::client {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::bytesOf;
using test::TestStreamServer;

using vem::testing::CommandRun;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class VemtoolSubscribeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("vemtool_subscribe_" + std::to_string(::getpid()) + "_" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs vemtool in the background (the test drives the server meanwhile).
  std::future<CommandRun> start(const std::string& args) const {
    return std::async(std::launch::async, [this, args] {
      return vem::testing::runCommand(vem::testing::commandLine(VEMTOOL_PATH, "subscribe " + args),
                                      dir_);
    });
  }
  fs::path dir_;
};

TEST_F(VemtoolSubscribeCli, PrintsOneJsonLinePerLightFrameAndTheStatistics) {
  TestStreamServer server(0, "tok");
  std::ofstream(dir_ / "token") << "tok\n";
  auto run = start(server.url() + " --token-file " + (dir_ / "token").string() +
                   " --what lights,cubemap --frames 3 --timeout 30");
  ASSERT_TRUE(server.waitForClientMessages(1, 20s));
  const stream::ClientMessage subscribe = server.clientMessages().at(0);
  EXPECT_TRUE(subscribe.subscribe().lights());
  EXPECT_EQ(subscribe.subscribe().cubemap_rate_hz(), 1.0);
  server.send(bytesOf(test::environmentMessage(1, 8, 1)));
  for (std::uint64_t seq : {1, 2, 4}) server.send(bytesOf(test::lightFrameMessage(seq, 2)));
  const CommandRun r = run.get();
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<std::string> out = lines(r.out);
  ASSERT_EQ(out.size(), 4U) << r.out;
  const auto cubemap = nlohmann::json::parse(out[0]);
  EXPECT_EQ(cubemap["cubemap"]["seq"], 1);
  EXPECT_EQ(cubemap["cubemap"]["face_px"], 8);
  EXPECT_EQ(cubemap["cubemap"]["levels"], 1);
  EXPECT_GT(cubemap["cubemap"]["bytes"].get<int>(), 0);
  const auto frame = nlohmann::json::parse(out[3]);
  EXPECT_EQ(frame["seq"], 4);
  EXPECT_EQ(frame["lights_seq"], 0);
  EXPECT_EQ(frame["capture_ts_ns"], 4 * 33'333'333LL);
  EXPECT_TRUE(frame["latency_ms"].is_number());
  EXPECT_EQ(frame["count"], 2);
  ASSERT_EQ(frame["lights"].size(), 2U);
  EXPECT_EQ(frame["lights"][1]["id"], 1);
  EXPECT_EQ(frame["lights"][1]["rgb"], nlohmann::json::parse("[2.0, 3.0, 0.5]"));
  EXPECT_EQ(frame["lights"][0]["dir"], nlohmann::json::parse("[1.0, 0.0, 0.0]"));
  const std::vector<std::string> err = lines(r.err);
  ASSERT_FALSE(err.empty());
  const auto stats = nlohmann::json::parse(err.back());
  EXPECT_EQ(stats["received"], 3);
  EXPECT_EQ(stats["skipped"], 1);
  EXPECT_EQ(stats["reconnects"], 0);
  EXPECT_TRUE(stats["latency_median_ms"].is_number());
  EXPECT_TRUE(stats["latency_p99_ms"].is_number());
}

TEST_F(VemtoolSubscribeCli, CubemapFaceAndLevelsAreAskedForAsGiven) {
  TestStreamServer server(0);
  auto run = start(server.url() +
                   " --what cubemap --cubemap-face 256 --cubemap-levels 4 --cubemap-rate 5 "
                   "--frames 1 --timeout 30");
  ASSERT_TRUE(server.waitForClientMessages(1, 20s));
  const stream::ClientMessage subscribe = server.clientMessages().at(0);
  EXPECT_FALSE(subscribe.subscribe().lights());
  EXPECT_EQ(subscribe.subscribe().cubemap_face_px(), 256u);
  EXPECT_EQ(subscribe.subscribe().cubemap_levels(), 4u);
  EXPECT_EQ(subscribe.subscribe().cubemap_rate_hz(), 5.0);
  server.send(bytesOf(test::environmentMessage(1, 8, 1)));
  const CommandRun r = run.get();
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(VemtoolSubscribeCli, ExitsWithTheSentenceWhenTheDaemonSpeaksMajor2) {
  TestStreamServer server(0, "", bytesOf(test::helloMessage(), 2));
  const CommandRun r = start(server.url() + " --frames 1 --timeout 30").get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("protocol major version 2 is not supported (this client speaks 1)"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
}

// Issue 17: `vemtool subscribe` to a dead port waited for ever (the client retries with backoff).
// --timeout bounds the wait for the connection and the first frame.
TEST_F(VemtoolSubscribeCli, GivesUpOnADeadPortAfterTheTimeoutNamingTheUrlInsteadOfWaitingForever) {
  std::uint16_t port = 0;
  { port = TestStreamServer().port(); }  // a port nobody listens on any more
  const std::string url = "ws://127.0.0.1:" + std::to_string(port) + "/";
  auto run = start(url + " --timeout 0.5");
  ASSERT_EQ(run.wait_for(60s), std::future_status::ready) << "subscribe did not give up";
  const CommandRun r = run.get();
  EXPECT_EQ(r.exitCode, 1);
  const std::vector<std::string> err = lines(r.err);
  ASSERT_FALSE(err.empty());
  EXPECT_TRUE(err.back().starts_with("vemtool: error: could not connect to " + url +
                                     " within 0.5 s (--timeout)"))
      << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST_F(VemtoolSubscribeCli, GivesUpWhenConnectedButNoFrameArrivesWithinTheTimeout) {
  TestStreamServer server(0);  // greets with a Hello, then sends nothing
  auto run = start(server.url() + " --timeout 0.5");
  ASSERT_EQ(run.wait_for(60s), std::future_status::ready) << "subscribe did not give up";
  const CommandRun r = run.get();
  EXPECT_EQ(r.exitCode, 1);
  const std::vector<std::string> err = lines(r.err);
  ASSERT_FALSE(err.empty());
  // Connected or still connecting when the half second ran out: either sentence names the URL.
  EXPECT_TRUE(err.back() == "vemtool: error: connected to " + server.url() +
                                " but no light frame arrived within 0.5 s (--timeout)" ||
              err.back().starts_with("vemtool: error: could not connect to " + server.url()))
      << r.err;
}

TEST_F(VemtoolSubscribeCli, DurationEndsTheRunAndFailsWhenFramesWereMissing) {
  TestStreamServer server(0);
  auto run = start(server.url() + " --frames 2 --duration 0.5 --timeout 30");
  ASSERT_TRUE(server.waitForClientMessages(1, 20s));
  server.send(bytesOf(test::lightFrameMessage(1, 2)));
  const CommandRun r = run.get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(
      r.err.find("stopped after 0.5 s (--duration) with 1 of 2 light frames from " + server.url()),
      std::string::npos)
      << r.err;
}

TEST_F(VemtoolSubscribeCli, RefusesAnAddressThatIsNotAStream) {
  const CommandRun r = start("http://127.0.0.1:1/ --frames 1").get();
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("is not a stream address"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vem::client
