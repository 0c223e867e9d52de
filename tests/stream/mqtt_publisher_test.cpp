// MqttPublisher in-process (daemon/stream/mqtt_publisher.h): the processing thread's calls against
// a broker that is down, control requests as the broker hands them over (checked by the WebSocket
// path's handler, answered on their response topic), and the fan-out's merge of two publishers.
// The broker is a real Mosquitto on 127.0.0.1 (tests/support/mosquitto_broker.h).
#include "stream/mqtt_publisher.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "proto/stream_protocol.h"
#include "stream/frame_encoding.h"
#include "stream/publisher_fan_out.h"
#include "support/mosquitto_broker.h"
#include "support/test_mqtt_publisher.h"

namespace vem::stream {
namespace {

using namespace std::chrono_literals;

// A loopback port nobody listens on (bound, then closed).
std::uint16_t closedPort() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  socklen_t length = sizeof(address);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(fd);
  return ntohs(address.sin_port);
}

MqttPublisherOptions optionsFor(std::uint16_t port) {
  MqttPublisherOptions options;
  options.port = port;
  options.cameraId = "cam1";
  options.queueMessages = 8;
  options.hello.set_server("vemd test");
  options.hello.set_source("synthetic:sky");
  return options;
}

SharedBytes lightsMessage(std::uint64_t seq) {
  ServerMessage message;
  message.mutable_lights()->set_seq(seq);
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

// Polls `done` (state of another thread or process: no event to wait on here) within `limit`.
template <class Done>
bool eventually(Done done, std::chrono::milliseconds limit = 10s) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(5ms);
  }
  return done();
}

TEST(MqttPublisher, ProcessingThreadHandsFramesOverWithoutWaitingForABrokerThatIsDown) {
  auto publisher = MqttPublisher::start(optionsFor(closedPort()));
  ASSERT_TRUE(publisher) << publisher.error();
  // Each call returns at once; the queue keeps the newest 8 and counts the rest as dropped.
  for (std::uint64_t seq = 0; seq < 1000; ++seq) (*publisher)->publishLights(lightsMessage(seq));
  const MqttCounters counters = (*publisher)->counters();
  EXPECT_FALSE(counters.connected);
  EXPECT_EQ(counters.queued, 1000U);
  EXPECT_EQ(counters.published, 0U);
  EXPECT_EQ(counters.dropped, 1000U - 8U);
  EXPECT_NE((*publisher)->note().find("not connected, 0 published, 992 dropped"),
            std::string::npos)
      << (*publisher)->note();
}

TEST(MqttPublisher, BadTopicLevelsAndHalfAClientCertificateAreRefusedInOneSentence) {
  MqttPublisherOptions wildcard = optionsFor(1883);
  wildcard.cameraId = "cam/+";
  auto refused = MqttPublisher::start(wildcard);
  ASSERT_FALSE(refused);
  EXPECT_TRUE(refused.error().starts_with("mqtt.camera_id: ")) << refused.error();
  MqttPublisherOptions halfCertificate = optionsFor(1883);
  halfCertificate.tls = true;
  halfCertificate.certFile = "/etc/hostname";
  refused = MqttPublisher::start(halfCertificate);
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("both or neither"), std::string::npos) << refused.error();
}

TEST(MqttPublisher, OnlyTheConfiguredCubeMapVariantIsAskedForAndPublished) {
  MqttPublisherOptions options = optionsFor(closedPort());
  options.cubemapRateHz = 2.0;
  options.cube = CubeVariant{128, 3, false};
  auto publisher = MqttPublisher::start(options);
  ASSERT_TRUE(publisher) << publisher.error();
  const CubemapDemand demand = (*publisher)->cubemapDemand();
  ASSERT_EQ(demand.variants.size(), 1U);
  EXPECT_EQ(demand.variants[0].variant, options.cube);
  EXPECT_EQ(demand.variants[0].rateHz, 2.0);
  // Another size (built for a WebSocket client) is not the broker's.
  (*publisher)->publishEnvironment(CubeVariant{64, 1, false}, lightsMessage(1));
  EXPECT_EQ((*publisher)->counters().queued, 0U);
  (*publisher)->publishEnvironment(options.cube, lightsMessage(2));
  (*publisher)->publishEnvironment(options.cube, lightsMessage(3));  // within 0.5 s: too soon
  EXPECT_EQ((*publisher)->counters().queued, 1U);
}

class MqttPublisherControl : public ::testing::Test {
 protected:
  void SetUp() override {
    auto broker = testing::MosquittoBroker::start();
    ASSERT_TRUE(broker) << broker.error();
    broker_ = std::move(*broker);
    auto publisher = MqttPublisher::start(optionsFor(broker_->port()));
    ASSERT_TRUE(publisher) << publisher.error();
    publisher_ = std::move(*publisher);
    ASSERT_TRUE(eventually([&] { return publisher_->counters().connected; }));
    requester_ = testing::TestMqttPublisher::connect(broker_->port());
    ASSERT_NE(requester_, nullptr);
    ASSERT_TRUE(requester_->answerControls("test/replies"));  // collects the replies
    // vemd subscribes to its control topic right after connecting: its SUBACK is not observable
    // here, so a first request is repeated until it is answered.
    ASSERT_TRUE(eventually([&] {
      request(std::string("\xff", 1), "warm-up");
      return requester_->waitForControls(1, 200ms);
    }));
    warmUpReplies_ = requester_->controls().size();
  }

  void request(const std::string& payload, const std::string& correlation,
               const std::string& responseTopic = "test/replies") {
    ASSERT_TRUE(requester_->publish(publisher_->topic("control"), payload, false, responseTopic,
                                    correlation));
  }

  // The n-th reply after the warm-up, decoded.
  std::pair<ControlReply, std::string> reply(std::size_t n) {
    EXPECT_TRUE(requester_->waitForControls(warmUpReplies_ + n + 1, 10s));
    const auto all = requester_->controls();
    if (all.size() <= warmUpReplies_ + n) return {};
    const auto& received = all[warmUpReplies_ + n];
    ServerMessage message;
    EXPECT_TRUE(message.ParseFromString(received.payload));
    EXPECT_TRUE(message.has_reply());
    return {message.reply(), received.correlationData};
  }

  static std::string control(std::uint64_t requestId, std::uint32_t lights) {
    ClientMessage message;
    message.set_protocol_major(kProtocolMajor);
    message.set_request_id(requestId);
    message.mutable_control()->set_set_light_count(lights);
    return message.SerializeAsString();
  }

  std::unique_ptr<testing::MosquittoBroker> broker_;
  std::unique_ptr<MqttPublisher> publisher_;
  std::unique_ptr<testing::TestMqttPublisher> requester_;
  std::size_t warmUpReplies_ = 0;
};

TEST_F(MqttPublisherControl, ValidControlReachesTheProcessingThreadAndItsReplyTheResponseTopic) {
  request(control(41, 64), "corr-41");
  std::vector<PendingControl> pending;
  ASSERT_TRUE(eventually([&] {
    auto taken = publisher_->takeControls();
    pending.insert(pending.end(), taken.begin(), taken.end());
    return !pending.empty();
  }));
  ASSERT_EQ(pending.size(), 1U);
  EXPECT_EQ(pending[0].requestId, 41U);
  EXPECT_EQ(pending[0].command.set_light_count(), 64U);
  ControlReply answer;
  answer.set_request_id(41);
  answer.set_ok(true);
  publisher_->reply(pending[0].connection, answer);
  const auto [replyMessage, correlation] = reply(0);
  EXPECT_TRUE(replyMessage.ok());
  EXPECT_EQ(replyMessage.request_id(), 41U);
  EXPECT_EQ(correlation, "corr-41");
}

TEST_F(MqttPublisherControl, BytesThatAreNoControlAreAnsweredWithTheWebSocketHandlersSentence) {
  request("not a protobuf \xff\xff", "corr-bad");
  const auto [replyMessage, correlation] = reply(0);
  EXPECT_FALSE(replyMessage.ok());
  EXPECT_FALSE(replyMessage.message().empty());
  EXPECT_EQ(correlation, "corr-bad");
  EXPECT_TRUE(publisher_->takeControls().empty());
}

TEST_F(MqttPublisherControl, OutOfRangeValuesAndSubscribesAreRefusedWithTheirReason) {
  request(control(7, 1'000'000), "range");
  ClientMessage subscribe;
  subscribe.set_protocol_major(kProtocolMajor);
  subscribe.set_request_id(8);
  subscribe.mutable_subscribe()->set_lights(true);
  request(subscribe.SerializeAsString(), "subscribe");
  request(std::string(kMaxClientMessageBytes + 1, 'x'), "too-big");
  const auto [range, c1] = reply(0);
  EXPECT_FALSE(range.ok());
  EXPECT_EQ(range.request_id(), 7U);
  EXPECT_NE(range.message().find("light"), std::string::npos) << range.message();
  const auto [subscribed, c2] = reply(1);
  EXPECT_FALSE(subscribed.ok());
  EXPECT_NE(subscribed.message().find("subscribes at the broker"), std::string::npos);
  const auto [big, c3] = reply(2);
  EXPECT_FALSE(big.ok());
  EXPECT_NE(big.message().find("at most 65536 bytes"), std::string::npos) << big.message();
  EXPECT_TRUE(publisher_->takeControls().empty());
  EXPECT_GE(publisher_->counters().controlsRefused, 3U);
}

TEST_F(MqttPublisherControl, ControlWithoutAResponseTopicIsAppliedAndItsReplyCounted) {
  request(control(9, 32), "", "");
  std::vector<PendingControl> pending;
  ASSERT_TRUE(eventually([&] {
    pending = publisher_->takeControls();
    return !pending.empty();
  }));
  ControlReply answer;
  answer.set_request_id(9);
  answer.set_ok(true);
  publisher_->reply(pending[0].connection, answer);
  EXPECT_EQ(publisher_->counters().repliesUnrouted, 1U);
}

// Two publishers behind one: both get every frame, and a reply goes back to the one whose client
// asked.
class RecordingPublisher final : public Publisher {
 public:
  void publishLights(SharedBytes) override { ++lights; }
  void publishEnvironment(const CubeVariant&, SharedBytes) override {}
  void publishStatus(const Status&) override {}
  [[nodiscard]] CubemapDemand cubemapDemand() const override { return demand; }
  [[nodiscard]] std::vector<PendingControl> takeControls() override {
    return std::exchange(pending, {});
  }
  void reply(std::uint64_t connection, const ControlReply&) override {
    repliedTo.push_back(connection);
  }
  int lights = 0;
  CubemapDemand demand;
  std::vector<PendingControl> pending;
  std::vector<std::uint64_t> repliedTo;
};

TEST(PublisherFanOut, RepliesGoBackToThePublisherTheirRequestCameFrom) {
  RecordingPublisher web, mqtt;
  web.pending.push_back({5, 1, {}});
  mqtt.pending.push_back({5, 2, {}});
  web.demand.variants = {{CubeVariant{64, 1, false}, 10.0}};
  mqtt.demand.variants = {{CubeVariant{64, 1, false}, 2.0}, {CubeVariant{128, 1, false}, 1.0}};
  PublisherFanOut both({&web, &mqtt});
  both.publishLights(lightsMessage(1));
  EXPECT_EQ(web.lights, 1);
  EXPECT_EQ(mqtt.lights, 1);
  const CubemapDemand merged = both.cubemapDemand();
  ASSERT_EQ(merged.variants.size(), 2U);
  EXPECT_EQ(merged.variants[0].rateHz, 10.0);  // 64 px at the higher of 10 and 2 Hz
  const std::vector<PendingControl> pending = both.takeControls();
  ASSERT_EQ(pending.size(), 2U);
  EXPECT_NE(pending[0].connection, pending[1].connection) << "two connections 5 told apart";
  both.reply(pending[1].connection, {});
  EXPECT_TRUE(web.repliedTo.empty());
  ASSERT_EQ(mqtt.repliedTo.size(), 1U);
  EXPECT_EQ(mqtt.repliedTo[0], 5U);
}

}  // namespace
}  // namespace vem::stream
