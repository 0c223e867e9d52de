// StreamClient over MQTT (client/mqtt_transport.h) against a real Mosquitto broker on 127.0.0.1
// (tests/support/mosquitto_broker.h), the test publishing with its own libmosquitto client in
// vemd's place (test_mqtt_publisher.h). Waits are bounded by generous timeouts only to fail
// instead of hanging; nothing asserts a duration.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "client/stream_client.h"
#include "client/stream_test_messages.h"
#include "support/test_mqtt_publisher.h"
#include "support/mosquitto_broker.h"

namespace vem::client {
namespace {

using namespace std::chrono_literals;
using test::bytesOf;
using test::lightFrameMessage;
using testing::TestMqttPublisher;
using vem::testing::MosquittoBroker;
using vem::testing::MosquittoBrokerConfig;

constexpr auto kWait = 10s;
constexpr const char* kCamera = "/vemcast/cam-1";
constexpr const char* kLights = "vemcast/cam-1/lights";

std::unique_ptr<MosquittoBroker> startBroker(MosquittoBrokerConfig config = {}) {
  auto broker = MosquittoBroker::start(std::move(config));
  EXPECT_TRUE(broker.has_value()) << broker.error();
  return broker ? std::move(*broker) : nullptr;
}

StreamClientOptions mqttOptions(const std::string& url) {
  StreamClientOptions options;
  options.url = url;
  options.initialBackoff = 10ms;
  options.maxBackoff = 100ms;
  return options;
}

std::unique_ptr<StreamClient> startClient(StreamClientOptions options) {
  auto client = StreamClient::start(std::move(options));
  EXPECT_TRUE(client.has_value()) << client.error();
  return client ? std::move(*client) : nullptr;
}

stream::ServerMessage statusMessage(bool offline) {
  stream::ServerMessage message;
  stream::Status& status = *message.mutable_status();
  status.set_source("synthetic:sky");
  status.set_state(stream::SOURCE_STATE_OK);
  status.set_frame_rate_hz(30.0);
  status.set_light_count(64);
  status.set_offline(offline);
  status.set_publish_dropped(3);
  return message;
}

// The default logger's lines while it lives (read them once the client has stopped).
class CapturedLog {
 public:
  CapturedLog() : previous_(spdlog::default_logger()) {
    auto logger = std::make_shared<spdlog::logger>(
        "test", std::make_shared<spdlog::sinks::ostream_sink_mt>(text_));
    logger->set_pattern("%l: %v");
    spdlog::set_default_logger(logger);
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;
  std::size_t linesContaining(const std::string& needle) {
    std::istringstream lines(text_.str());
    std::size_t count = 0;
    for (std::string line; std::getline(lines, line);) count += line.find(needle) != line.npos;
    return count;
  }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::logger> previous_;
};

TEST(MqttStreamClient, FramesPublishedAfterTheSubscriptionArriveInOrder) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  std::mutex mutex;
  std::vector<std::uint64_t> seqs;
  StreamClientOptions options = mqttOptions(broker->url(kCamera));
  options.onLightFrame = [&](const Received<LightFrame>& r) {
    std::lock_guard lock(mutex);
    seqs.push_back(r.frame.seq);
  };
  auto client = startClient(std::move(options));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  for (std::uint64_t seq = 1; seq <= 5; ++seq) {
    ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(seq, 4)), true));
  }
  const auto last = client->waitForLightFrame(4, kWait);
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->frame.lights.lights.size(), 4U);
  client->stop();
  EXPECT_EQ(seqs, (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
  const ClientStats stats = client->stats();
  EXPECT_EQ(stats.received, 5U);
  EXPECT_EQ(stats.skipped, 0U);
  EXPECT_EQ(stats.decodeErrors, 0U);
  EXPECT_EQ(stats.reconnects, 0U);
}

TEST(MqttStreamClient, ALateSubscriberGetsTheRetainedHelloStatusAndLightFrameAtOnce) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish("vemcast/cam-1/hello", bytesOf(test::helloMessage()), true));
  ASSERT_TRUE(vemd->publish("vemcast/cam-1/status", bytesOf(statusMessage(false)), true));
  for (std::uint64_t seq : {6, 7}) {
    ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(seq)), true));
  }
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  const auto frame = client->waitForLightFrame(std::nullopt, kWait);
  ASSERT_TRUE(frame.has_value()) << client->stateReason();
  EXPECT_EQ(frame->frame.seq, 7U);  // the retained one, only
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  ASSERT_TRUE(client->hello().has_value());
  EXPECT_EQ(client->hello()->server, "fixture 1.0");
  ASSERT_TRUE(client->status().has_value());
  EXPECT_EQ(client->status()->frameRateHz, 30.0);
  EXPECT_EQ(client->stats().received, 1U);
}

TEST(MqttStreamClient, ARetainedOfflineStatusIsJustAStatus) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish("vemcast/cam-1/status", bytesOf(statusMessage(true)), true));
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(1)), true));
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForLightFrame(std::nullopt, kWait).has_value());  // after the status
  ASSERT_TRUE(client->status().has_value());
  EXPECT_TRUE(client->status()->offline);
  EXPECT_EQ(client->status()->publishDropped, 3U);
  // Connected (both SUBACKs) may come just after the retained frames.
  EXPECT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
}

// A WebSocket client closes the connection on a message it refuses; over MQTT there is no
// connection of the daemon's to close: the client logs the refusal once, counts every one, and
// keeps its subscription.
TEST(MqttStreamClient, AMalformedPayloadIsRefusedOnceInTheLogCountedAndTheNextFrameStillArrives) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  CapturedLog log;
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  stream::ServerMessage bad = lightFrameMessage(1);
  bad.mutable_lights()->set_dirs(0, 7.0F);
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(bad)));
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(bad)));
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(2))));
  const auto frame = client->waitForLightFrame(std::nullopt, kWait);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->frame.seq, 2U);
  EXPECT_EQ(client->state(), ConnectionState::Connected);
  client->stop();
  EXPECT_EQ(client->stats().decodeErrors, 2U);
  EXPECT_EQ(client->stats().received, 1U);
  EXPECT_EQ(client->stats().reconnects, 0U);
  EXPECT_EQ(log.linesContaining("the payload on vemcast/cam-1/lights is refused: "), 1U);
}

TEST(MqttStreamClient, APayloadOfAnotherProtocolMajorStopsTheClientWithTheDecodersSentence) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish("vemcast/cam-1/hello", bytesOf(test::helloMessage(), 2), true));
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Refused, kWait)) << client->stateReason();
  EXPECT_EQ(client->stateReason(),
            "protocol major version 2 is not supported (this client speaks 1)");
  EXPECT_EQ(client->stats().decodeErrors, 1U);
}

TEST(MqttStreamClient, AKilledBrokerRestartedOnTheSamePortIsFoundAgainWithoutHelp) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  {
    auto vemd = TestMqttPublisher::connect(broker->port());
    ASSERT_NE(vemd, nullptr);
    ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(1)), true));
    ASSERT_TRUE(client->waitForLightFrame(std::nullopt, kWait).has_value());
    broker->kill();
  }
  ASSERT_TRUE(client->waitForState(ConnectionState::Waiting, kWait));
  EXPECT_TRUE(client->stateReason().starts_with("the connection to the broker 127.0.0.1:" +
                                                std::to_string(broker->port())))
      << client->stateReason();
  ASSERT_TRUE(broker->restart().has_value());
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  EXPECT_EQ(client->stats().reconnects, 1U);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(10)), true));
  const auto frame = client->waitForLightFrame(1, kWait);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->frame.seq, 10U);
}

TEST(MqttStreamClient, ABrokerDownAtStartIsWaitedForWithTheSentenceNamingIt) {
  std::uint16_t port = 0;
  {
    auto broker = startBroker();
    ASSERT_NE(broker, nullptr);
    port = broker->port();
  }  // nobody listens there any more
  auto client = startClient(mqttOptions("mqtt://127.0.0.1:" + std::to_string(port) + kCamera));
  ASSERT_TRUE(client->waitForState(ConnectionState::Waiting, kWait));
  EXPECT_EQ(client->stateReason(), "the connection to the broker 127.0.0.1:" +
                                       std::to_string(port) + " failed: Connection refused");
}

TEST(MqttStreamClient, BadCredentialsAreRefusedForGoodWithTheBrokersReason) {
  MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"viewer", "right"}};
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  StreamClientOptions options =
      mqttOptions("mqtt://viewer@127.0.0.1:" + std::to_string(broker->port()) + kCamera);
  options.password = "wrong";
  auto client = startClient(std::move(options));
  ASSERT_TRUE(client->waitForState(ConnectionState::Refused, kWait)) << client->stateReason();
  EXPECT_EQ(client->stateReason(), "the broker 127.0.0.1:" + std::to_string(broker->port()) +
                                       " refused the connection: not authorized");

  StreamClientOptions right = mqttOptions(broker->url(kCamera));
  right.username = "viewer";
  right.password = "right";
  auto allowed = startClient(std::move(right));
  ASSERT_TRUE(allowed->waitForState(ConnectionState::Connected, kWait)) << allowed->stateReason();
}

TEST(MqttStreamClient, AControlReplyOnTheResponseTopicFulfilsTheFuture) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->answerControls("vemcast/cam-1/control"));
  auto client = startClient(mqttOptions(broker->url(kCamera)));  // no token over MQTT
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  stream::Control control;
  control.set_set_filter("paper9");
  auto future = client->sendControl(control);
  ASSERT_EQ(future.wait_for(kWait), std::future_status::ready);
  const ControlResult result = future.get();
  ASSERT_TRUE(result.has_value()) << result.error();
  EXPECT_TRUE(result->ok);
  ASSERT_TRUE(vemd->waitForControls(1, kWait));
  const auto received = vemd->controls().at(0);
  EXPECT_EQ(received.message.control().set_filter(), "paper9");
  EXPECT_EQ(received.message.protocol_major(), 1U);
  EXPECT_EQ(result->requestId, received.message.request_id());
  EXPECT_TRUE(received.responseTopic.starts_with("vemcast/cam-1/reply/vemcast-"))
      << received.responseTopic;
  ASSERT_EQ(received.correlationData.size(), 8U);
  std::uint64_t correlated = 0;
  for (char byte : received.correlationData) correlated = (correlated << 8) | std::uint8_t(byte);
  EXPECT_EQ(correlated, result->requestId);
}

TEST(MqttStreamClient, AControlTheAclForbidsFailsWithTheBrokersReason) {
  MosquittoBrokerConfig config;
  config.allowAnonymous = false;
  config.users = {{"viewer", "look"}};
  config.acl = "user viewer\ntopic read vemcast/#";
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  StreamClientOptions options = mqttOptions(broker->url(kCamera));
  options.username = "viewer";
  options.password = "look";
  auto client = startClient(std::move(options));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  stream::Control control;
  control.set_set_light_count(16);
  auto future = client->sendControl(control);
  ASSERT_EQ(future.wait_for(kWait), std::future_status::ready);
  const ControlResult result = future.get();
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error(), "the broker refused the control message: not authorized");
}

// The broker answers a control nobody subscribes to with PUBACK 16: no reply will ever come.
TEST(MqttStreamClient, AControlNoDaemonListensForFailsInsteadOfWaitingForAReply) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
  stream::Control control;
  control.set_set_light_count(16);
  auto future = client->sendControl(control);
  ASSERT_EQ(future.wait_for(kWait), std::future_status::ready);
  const ControlResult result = future.get();
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error(),
            "no daemon listens on vemcast/cam-1/control: the broker found no matching subscribers");
}

TEST(MqttStreamClient, AControlWithoutAConnectionFailsAtOnce) {
  auto client = startClient(mqttOptions("mqtt://127.0.0.1:1/vemcast/cam-1"));
  stream::Control control;
  control.set_set_light_count(16);
  auto future = client->sendControl(control);
  ASSERT_EQ(future.wait_for(kWait), std::future_status::ready);
  const ControlResult result = future.get();
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error(), "the client is not connected to the broker");
}

TEST(MqttStreamClient, MqttsWithTheTestCaConnectsAndWithoutItFailsNamingTheVerification) {
  MosquittoBrokerConfig config;
  config.tls = true;
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  StreamClientOptions trusted = mqttOptions(broker->tlsUrl(kCamera));
  trusted.caFile = broker->caFile().string();
  auto client = startClient(std::move(trusted));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();

  auto stranger = startClient(mqttOptions(broker->tlsUrl(kCamera)));  // the system's CAs
  ASSERT_TRUE(stranger->waitForState(ConnectionState::Waiting, kWait));
  EXPECT_EQ(stranger->stateReason(),
            "the connection to the broker 127.0.0.1:" + std::to_string(broker->tlsPort()) +
                " failed: TLS: certificate verify failed");
}

TEST(MqttStreamClient, AClientCertificateSignedByTheBrokersCaIsAccepted) {
  MosquittoBrokerConfig config;
  config.tls = true;
  config.requireClientCertificate = true;
  auto broker = startBroker(config);
  ASSERT_NE(broker, nullptr);
  const auto certificate = broker->issueClientCertificate("renderer");
  ASSERT_TRUE(certificate.has_value()) << certificate.error();
  StreamClientOptions options = mqttOptions(broker->tlsUrl(kCamera));
  options.caFile = broker->caFile().string();
  options.certFile = certificate->cert.string();
  options.keyFile = certificate->key.string();
  auto client = startClient(std::move(options));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait)) << client->stateReason();
}

TEST(MqttStreamClient, RefusesACertificateWithoutItsKeyAndOneWithoutTls) {
  StreamClientOptions halves = mqttOptions("mqtts://127.0.0.1/vemcast/cam-1");
  halves.certFile = "/etc/hostname";
  const auto client = StreamClient::start(std::move(halves));
  ASSERT_FALSE(client.has_value());
  EXPECT_EQ(client.error(), "a client certificate needs its key, and a key its certificate");
  StreamClientOptions plain = mqttOptions("mqtt://127.0.0.1/vemcast/cam-1");
  plain.certFile = plain.keyFile = "/etc/hostname";
  const auto other = StreamClient::start(std::move(plain));
  ASSERT_FALSE(other.has_value());
  EXPECT_EQ(other.error(), "a client certificate needs TLS (an mqtts:// address)");
}

TEST(MqttStreamClient, TheCubemapTopicIsSubscribedToOnlyWhenCubeMapsAreAskedFor) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  StreamClientOptions withCubes = mqttOptions(broker->url(kCamera));
  withCubes.subscription.cubemapRateHz = 1.0;
  auto cubes = startClient(std::move(withCubes));
  auto lightsOnly = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(cubes->waitForState(ConnectionState::Connected, kWait));
  ASSERT_TRUE(lightsOnly->waitForState(ConnectionState::Connected, kWait));
  auto vemd = TestMqttPublisher::connect(broker->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish("vemcast/cam-1/cubemap", bytesOf(test::environmentMessage(5, 8, 2))));
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(6))));  // after the cube map
  ASSERT_TRUE(cubes->waitForLightFrame(std::nullopt, kWait).has_value());
  ASSERT_TRUE(lightsOnly->waitForLightFrame(std::nullopt, kWait).has_value());
  ASSERT_TRUE(cubes->latestEnvironmentFrame().has_value());
  EXPECT_EQ(cubes->latestEnvironmentFrame()->frame.seq, 5U);
  EXPECT_EQ(cubes->stats().environmentFrames, 1U);
  EXPECT_FALSE(lightsOnly->latestEnvironmentFrame().has_value());
}

TEST(MqttStreamClient, StopSaysGoodbyeInsteadOfDroppingTheConnection) {
  auto broker = startBroker();
  ASSERT_NE(broker, nullptr);
  auto client = startClient(mqttOptions(broker->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  client->stop();
  EXPECT_EQ(client->state(), ConnectionState::Stopped);
  // "Client ID disconnected." after a DISCONNECT; "Client ID closed its connection." without one
  // (as after the fixture's own probes of the port, from "Client <unknown>").
  ASSERT_TRUE(broker->waitForLog(" disconnected.", kWait)) << broker->logText();
  std::istringstream lines(broker->logText());
  for (std::string line; std::getline(lines, line);) {
    EXPECT_FALSE(line.find("Client vemcast-") != line.npos &&
                 line.find("closed its connection") != line.npos)
        << line;
  }
}

TEST(MqttStreamClient, BridgedBrokersCarryTheFramesToTheFarSide) {
  auto site = startBroker();
  ASSERT_NE(site, nullptr);
  MosquittoBrokerConfig config;
  config.bridge = vem::testing::MosquittoBridge{site->port(), "vemcast/#", "both"};
  auto far = startBroker(config);
  ASSERT_NE(far, nullptr);
  auto client = startClient(mqttOptions(far->url(kCamera)));
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  auto vemd = TestMqttPublisher::connect(site->port());
  ASSERT_NE(vemd, nullptr);
  ASSERT_TRUE(vemd->publish(kLights, bytesOf(lightFrameMessage(3)), true));
  const auto frame = client->waitForLightFrame(std::nullopt, kWait);
  ASSERT_TRUE(frame.has_value()) << far->logText();
  EXPECT_EQ(frame->frame.seq, 3U);
}

}  // namespace
}  // namespace vem::client
