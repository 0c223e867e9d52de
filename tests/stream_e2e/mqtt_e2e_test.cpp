// End to end through an MQTT broker (issue 22): the real vemd publishing to a real Mosquitto on
// 127.0.0.1 (tests/support/mosquitto_broker.h), read by the client library's MQTT transport and by
// the real vemtool. Each test names the bug it catches.
#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/test_mqtt_publisher.h"
#include "stream_e2e/stream_e2e_fixture.h"
#include "support/command_run.h"
#include "support/mosquitto_broker.h"

namespace vem::e2e {
namespace {

namespace fs = std::filesystem;
using testing::MosquittoBroker;
using testing::MosquittoBrokerConfig;

constexpr const char* kCamera = "cam1";

class MqttE2eTest : public StreamE2eTest {
 protected:
  // The broker, or a failed test.
  std::unique_ptr<MosquittoBroker> startBroker(MosquittoBrokerConfig config = {}) {
    auto broker = MosquittoBroker::start(std::move(config));
    EXPECT_TRUE(broker.has_value()) << (broker ? "" : broker.error());
    return broker ? std::move(*broker) : nullptr;
  }

  // vemd publishing to `url` (and serving WebSocket clients, as every test of the fixture); `more`
  // holds further [mqtt] keys.
  std::optional<std::uint16_t> startPublishingVemd(const std::string& url,
                                                   const std::string& more = "",
                                                   const std::vector<std::string>& args = {}) {
    return startVemd(args, "[mqtt]\nurl = \"" + url + "\"\ncamera_id = \"" + kCamera + "\"\n" + more);
  }

  // A client of the camera's MQTT stream, logging its light frames.
  static LoggedClient startMqttClient(const std::string& url,
                                      const std::function<void(client::StreamClientOptions&)>& more =
                                          {}) {
    LoggedClient logged;
    client::StreamClientOptions options;
    options.url = url;
    options.connectTimeout = 20s;
    options.initialBackoff = 100ms;
    options.maxBackoff = 1000ms;
    options.onLightFrame = [log = logged.log.get()](const auto& received) { log->record(received); };
    if (more) more(options);
    auto started = client::StreamClient::start(std::move(options));
    EXPECT_TRUE(started.has_value()) << (started ? "" : started.error());
    if (started) logged.client = std::move(*started);
    return logged;
  }

  // Polls `done` every 10 ms until it holds or `timeout` passes (what it waits for is published by
  // another process: there is no event to wait on in this one).
  template <class Done>
  static bool eventually(Done done, std::chrono::milliseconds timeout = kFrameTimeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      if (done()) return true;
      std::this_thread::sleep_for(10ms);
    }
    return done();
  }

  static std::string cameraPath() { return std::string("/vemcast/") + kCamera; }
};

// The frames of one client keyed by seq: their lights' digest.
std::map<std::uint64_t, std::uint64_t> digestsBySeq(const LightFrameLog& log) {
  std::map<std::uint64_t, std::uint64_t> out;
  for (const LoggedFrame& frame : log.frames()) out[frame.seq] = frame.lightsDigest;
  return out;
}

TEST_F(MqttE2eTest, FramesThroughTheBrokerArriveInOrderAndEqualTheWebSocketStreamsFrames) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  const auto port = startPublishingVemd(broker->url());
  ASSERT_TRUE(port);
  LoggedClient ws = startClient(*port);
  LoggedClient mqtt = startMqttClient(broker->url(cameraPath()));
  ASSERT_TRUE(ws.client && mqtt.client);
  const auto first = mqtt.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(first) << mqtt.client->stateReason();
  std::vector<LoggedClient> both;
  both.push_back(std::move(ws));
  both.push_back(std::move(mqtt));
  ASSERT_TRUE(waitForSeq(both, first->frame.seq + 60));
  const auto wsFrames = digestsBySeq(*both[0].log);
  const std::vector<LoggedFrame> mqttFrames = both[1].log->frames();
  // In order: each seq above the one before (a retained frame first may repeat nothing).
  for (std::size_t i = 1; i < mqttFrames.size(); ++i) {
    EXPECT_GT(mqttFrames[i].seq, mqttFrames[i - 1].seq) << "frame " << i;
  }
  std::size_t compared = 0;
  for (const LoggedFrame& frame : mqttFrames) {
    const auto it = wsFrames.find(frame.seq);
    if (it == wsFrames.end()) continue;
    EXPECT_EQ(frame.lightsDigest, it->second) << "seq " << frame.seq;
    ++compared;
  }
  EXPECT_GE(compared, 50U);
  EXPECT_LE(missingSeqs(both[1].log->framesBetween(first->frame.seq + 1, first->frame.seq + 60)),
            mostMissing(60));
  both.clear();
  expectCleanExit(SIGTERM);
}

TEST_F(MqttE2eTest, VemtoolSubscribePrintsTheSameJsonThroughTheBrokerAsOverWebSocket) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  const auto port = startPublishingVemd(broker->url());
  ASSERT_TRUE(port);
  // Both subscribers at once, 90 frames each: their seqs overlap.
  const auto run = [this](const std::string& name, const std::string& url) {
    const fs::path dir = dir_ / name;
    fs::create_directories(dir);
    return testing::runCommand(
        testing::commandLine(VEMTOOL_PATH, "subscribe " + url + " --frames 90 --timeout 60"), dir);
  };
  testing::CommandRun wsRun, mqttRun;
  std::thread wsThread([&] { wsRun = run("ws", "ws://127.0.0.1:" + std::to_string(*port)); });
  mqttRun = run("mqtt", broker->url(cameraPath()));
  wsThread.join();
  ASSERT_EQ(wsRun.exitCode, 0) << wsRun.err;
  ASSERT_EQ(mqttRun.exitCode, 0) << mqttRun.err;
  // Each line less its latency (the receipt time differs), by seq.
  const auto bySeq = [](const std::string& out) {
    std::map<std::uint64_t, std::string> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) {
      auto json = nlohmann::ordered_json::parse(line);
      json.erase("latency_ms");
      lines[json["seq"].get<std::uint64_t>()] = json.dump();
    }
    return lines;
  };
  const auto wsLines = bySeq(wsRun.out);
  const auto mqttLines = bySeq(mqttRun.out);
  std::size_t compared = 0;
  for (const auto& [seq, line] : mqttLines) {
    const auto it = wsLines.find(seq);
    if (it == wsLines.end()) continue;
    EXPECT_EQ(line, it->second) << "seq " << seq;
    ++compared;
  }
  EXPECT_GE(compared, 30U) << "the two runs overlapped by too few frames to compare";
  expectCleanExit(SIGTERM);
}

TEST_F(MqttE2eTest, LateSubscriberGetsTheLastFrameAndTheGoodbyeAtOnceAfterVemdStopped) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  LoggedClient early = startMqttClient(broker->url(cameraPath()));
  ASSERT_TRUE(startPublishingVemd(broker->url(), "", {"--frames", "40"}));
  expectCleanExit(0);  // vemd ends by itself after 40 frames
  ASSERT_TRUE(eventually([&] { return early.log->size() > 0; }));
  const std::uint64_t lastSeq = early.log->frames().back().seq;
  // A subscriber arriving now, with vemd gone: the retained frame, the newest, at once.
  LoggedClient late = startMqttClient(broker->url(cameraPath()));
  const auto frame = late.client->waitForLightFrame(std::nullopt, 10s);
  ASSERT_TRUE(frame) << late.client->stateReason();
  EXPECT_EQ(frame->frame.seq, lastSeq);
  ASSERT_TRUE(eventually([&] { return late.client->status().has_value(); }, 10s));
  EXPECT_TRUE(late.client->status()->offline) << "a clean stop publishes the camera offline";
  ASSERT_TRUE(late.client->hello().has_value());
  EXPECT_FALSE(late.client->hello()->controlAllowed);
}

TEST_F(MqttE2eTest, WillMarksTheCameraOfflineWhenVemdIsKilled) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  ASSERT_TRUE(startPublishingVemd(broker->url()));
  LoggedClient watcher = startMqttClient(broker->url(cameraPath()));
  ASSERT_TRUE(eventually([&] {
    const auto status = watcher.client->status();
    return status && !status->offline && status->framesProcessed > 0;
  })) << "no status from a running vemd";
  vemd_->signal(SIGKILL);
  ASSERT_TRUE(vemd_->waitForExit(kExitTimeout));
  // The broker sees the connection drop with the process and publishes the will.
  ASSERT_TRUE(eventually([&] { return watcher.client->status()->offline; }, 15s))
      << "the will did not arrive";
  EXPECT_EQ(watcher.client->status()->source, "synthetic:sky");
}

TEST_F(MqttE2eTest, BrokerKilledMidStreamNeitherStopsNorSlowsVemdAndEveryoneResumes) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  const fs::path jsonl = dir_ / "lights.jsonl";
  const fs::path recording = dir_ / "run.vem";
  const auto port = startPublishingVemd(broker->url(), "",
                                        {"--jsonl", jsonl.string(), "--record", recording.string()});
  ASSERT_TRUE(port);
  LoggedClient ws = startClient(*port);
  LoggedClient mqtt = startMqttClient(broker->url(cameraPath()));
  const auto before = mqtt.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(before) << mqtt.client->stateReason();

  broker->kill();
  ASSERT_TRUE(mqtt.client->waitForState(client::ConnectionState::Waiting, 10s));
  const auto wsAtKill = ws.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(wsAtKill);
  // Three seconds of frames while the broker is down: capture and the other sinks go on at the
  // camera's rate, and the queue for the broker overflows.
  const std::uint64_t outage = std::uint64_t(kNominalRateHz * 3.0);
  std::vector<LoggedClient> wsOnly;
  wsOnly.push_back(std::move(ws));
  ASSERT_TRUE(waitForSeq(wsOnly, wsAtKill->frame.seq + outage)) << "vemd stalled without a broker";

  ASSERT_TRUE(broker->restart().has_value());
  const auto after = mqtt.client->waitForLightFrame(wsAtKill->frame.seq + outage, kFrameTimeout);
  ASSERT_TRUE(after) << "the client did not resume: " << mqtt.client->stateReason();
  // Frames may come before the last SUBACK, which makes the connection count.
  ASSERT_TRUE(mqtt.client->waitForState(client::ConnectionState::Connected, 10s));
  EXPECT_GE(mqtt.client->stats().reconnects, 1U);
  // vemd's status on the broker counts what it could not send meanwhile.
  ASSERT_TRUE(eventually([&] {
    const auto status = mqtt.client->status();
    return status && status->publishDropped > 0;
  })) << "no drops counted in the status";
  std::size_t jsonLines = 0;
  {
    std::ifstream in(jsonl);
    for (std::string line; std::getline(in, line);) ++jsonLines;
  }
  EXPECT_GE(jsonLines, outage) << "the JSON-lines sink stopped with the broker";
  wsOnly.clear();
  expectCleanExit(SIGTERM);
  // The recorder went on too: the frames of the outage are in the recording (all of them but
  // what two loaded cores may make the capture queue drop; a processing thread held up by the
  // broker would miss nearly all).
  const std::vector<std::uint64_t> recorded = recordedSeqs(recording);
  std::uint64_t notRecorded = 0;
  for (std::uint64_t seq = wsAtKill->frame.seq; seq <= wsAtKill->frame.seq + outage; ++seq) {
    if (!std::ranges::binary_search(recorded, seq)) ++notRecorded;
  }
  EXPECT_LE(notRecorded, mostMissing(outage));
}

TEST_F(MqttE2eTest, BridgedSecondBrokerDeliversTheCameraToItsSubscribers) {
  auto first = startBroker();
  ASSERT_NE(first, nullptr);
  MosquittoBrokerConfig bridged;
  bridged.bridge = testing::MosquittoBridge{first->port(), "vemcast/#", "in"};
  auto second = startBroker(bridged);
  ASSERT_NE(second, nullptr);
  ASSERT_TRUE(startPublishingVemd(first->url()));
  LoggedClient far = startMqttClient(second->url(cameraPath()));
  const auto frame = far.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(frame) << far.client->stateReason();
  EXPECT_TRUE(far.client->waitForLightFrame(frame->frame.seq + 10, kFrameTimeout));
  expectCleanExit(SIGTERM);
}

// The users of config/mosquitto/vemcast.acl, as shipped.
MosquittoBrokerConfig shippedAcl() {
  MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"vemd", "vemd-secret-1"}, {"viewer", "viewer-secret-1"},
                  {"operator", "operator-secret-1"}};
  config.acl = testing::readTextFile(fs::path(VEM_SOURCE_DIR) / "config" / "mosquitto" /
                                     "vemcast.acl");
  return config;
}

TEST_F(MqttE2eTest, ShippedAclRefusesControlFromAViewerWithAReasonAndLetsTheOperatorControl) {
  MosquittoBrokerConfig config = shippedAcl();
  ASSERT_FALSE(config.acl.empty());
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  const fs::path credentials =
      writeFile("mqtt.toml", "username = \"vemd\"\npassword = \"vemd-secret-1\"\n");
  ASSERT_TRUE(startPublishingVemd(broker->url(),
                                  "credentials_file = \"" + credentials.string() + "\"\n"));
  const auto as = [](const std::string& user, const std::string& password) {
    return [user, password](client::StreamClientOptions& o) {
      o.username = user;
      o.password = password;
    };
  };
  LoggedClient viewer = startMqttClient(broker->url(cameraPath()), as("viewer", "viewer-secret-1"));
  LoggedClient op = startMqttClient(broker->url(cameraPath()), as("operator", "operator-secret-1"));
  ASSERT_TRUE(viewer.client->waitForLightFrame(std::nullopt, kFrameTimeout))
      << viewer.client->stateReason();
  ASSERT_TRUE(op.client->waitForLightFrame(std::nullopt, kFrameTimeout)) << op.client->stateReason();

  stream::Control control;
  control.set_set_light_count(64);
  auto refused = viewer.client->sendControl(control);
  ASSERT_EQ(refused.wait_for(20s), std::future_status::ready);
  const client::ControlResult refusedResult = refused.get();
  ASSERT_FALSE(refusedResult.has_value()) << "a read-only viewer controlled vemd";
  EXPECT_NE(refusedResult.error().find("not authorized"), std::string::npos)
      << refusedResult.error();

  auto answered = op.client->sendControl(control);
  ASSERT_EQ(answered.wait_for(20s), std::future_status::ready);
  const client::ControlResult answer = answered.get();
  ASSERT_TRUE(answer.has_value()) << answer.error();
  EXPECT_TRUE(answer->ok) << answer->message;
  const auto latest = op.client->latestLightFrame();
  ASSERT_TRUE(latest);
  const auto frame = op.client->waitForLightFrame(latest->frame.seq + 5, kFrameTimeout);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->frame.lights.lights.size(), 64U);

  // vemd checks the operator's values with the WebSocket path's rules.
  stream::Control tooMany;
  tooMany.set_set_light_count(1'000'000);
  auto outOfRange = op.client->sendControl(tooMany);
  ASSERT_EQ(outOfRange.wait_for(20s), std::future_status::ready);
  const client::ControlResult rangeAnswer = outOfRange.get();
  ASSERT_TRUE(rangeAnswer.has_value()) << rangeAnswer.error();
  EXPECT_FALSE(rangeAnswer->ok);
  EXPECT_NE(rangeAnswer->message.find("light"), std::string::npos) << rangeAnswer->message;
  viewer.client.reset();
  op.client.reset();
  expectCleanExit(SIGTERM);
}

TEST_F(MqttE2eTest, MalformedPayloadOnTheLightsTopicIsRefusedWithoutStoppingTheClient) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  ASSERT_TRUE(startPublishingVemd(broker->url()));
  LoggedClient mqtt = startMqttClient(broker->url(cameraPath()));
  const auto first = mqtt.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(first) << mqtt.client->stateReason();
  auto intruder = testing::TestMqttPublisher::connect(broker->port());
  ASSERT_NE(intruder, nullptr);
  ASSERT_TRUE(intruder->publish(std::string("vemcast/") + kCamera + "/lights",
                                std::string("\x08\x01\x12\xff\xff not a message", 20)));
  ASSERT_TRUE(eventually([&] { return mqtt.client->stats().decodeErrors >= 1; }));
  const auto latest = mqtt.client->latestLightFrame();
  ASSERT_TRUE(latest);
  EXPECT_TRUE(mqtt.client->waitForLightFrame(latest->frame.seq + 5, kFrameTimeout))
      << "the client stopped after a malformed payload";
  EXPECT_EQ(mqtt.client->state(), client::ConnectionState::Connected);
  expectCleanExit(SIGTERM);
}

TEST_F(MqttE2eTest, TlsBrokerIsReachedByATrustingClientAndRefusedByOneWithoutTheCa) {
  MosquittoBrokerConfig config;
  config.tls = true;
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  ASSERT_TRUE(startPublishingVemd(broker->tlsUrl(),
                                  "tls_ca = \"" + broker->caFile().string() + "\"\n"));
  LoggedClient trusting = startMqttClient(
      broker->tlsUrl(cameraPath()),
      [&](client::StreamClientOptions& o) { o.caFile = broker->caFile().string(); });
  ASSERT_TRUE(trusting.client->waitForLightFrame(std::nullopt, kFrameTimeout))
      << trusting.client->stateReason();
  // The system's CAs do not know the test CA: the handshake fails, and the client says why.
  LoggedClient doubting = startMqttClient(broker->tlsUrl(cameraPath()));
  EXPECT_FALSE(doubting.client->waitForLightFrame(std::nullopt, 3s));
  EXPECT_NE(doubting.client->state(), client::ConnectionState::Connected);
  EXPECT_FALSE(doubting.client->stateReason().empty());
  expectCleanExit(SIGTERM);
}

TEST_F(MqttE2eTest, BrokerThatRequiresClientCertificatesTakesVemdsAndItsFramesFlow) {
  MosquittoBrokerConfig config;
  config.tls = true;
  config.requireClientCertificate = true;
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  const auto vemdCertificate = broker->issueClientCertificate("vemd");
  ASSERT_TRUE(vemdCertificate) << vemdCertificate.error();
  const auto viewerCertificate = broker->issueClientCertificate("viewer");
  ASSERT_TRUE(viewerCertificate) << viewerCertificate.error();
  ASSERT_TRUE(startPublishingVemd(broker->tlsUrl(),
                                  "tls_ca = \"" + broker->caFile().string() + "\"\ntls_cert = \"" +
                                      vemdCertificate->cert.string() + "\"\ntls_key = \"" +
                                      vemdCertificate->key.string() + "\"\n"));
  LoggedClient viewer = startMqttClient(broker->tlsUrl(cameraPath()), [&](auto& o) {
    o.caFile = broker->caFile().string();
    o.certFile = viewerCertificate->cert.string();
    o.keyFile = viewerCertificate->key.string();
  });
  ASSERT_TRUE(viewer.client->waitForLightFrame(std::nullopt, kFrameTimeout))
      << viewer.client->stateReason() << "\n" << vemd_->stderrText();
  expectCleanExit(SIGTERM);
}

}  // namespace
}  // namespace vem::e2e
