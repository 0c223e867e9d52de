// TestMqttPublisher: the tests' own libmosquitto client (MQTT 5) standing in for vemd on a broker
// of tests/support/mosquitto_broker.h: it publishes payloads, retained or not, each call returning
// once the broker has them (QoS 1, its PUBACK; subscribers at QoS 0 still get them at QoS 0, as
// from vemd), so a client that connects afterwards finds the retained one; and it can play vemd's
// control side:
// subscribe to a control topic, record each ClientMessage with its Response Topic and Correlation
// Data, and answer it with a ControlReply (ok) on the response topic, echoing the correlation
// data. Not production code: vemd's publisher is daemon/stream/. Its own libmosquitto thread
// (mosquitto_loop_start); every wait is bounded (10 s); members are thread-safe.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "proto/vem_stream.pb.h"

struct mosquitto;

namespace vem::testing {

class TestMqttPublisher {
 public:
  // Connected to 127.0.0.1:port (CONNACK success), or null with a test failure added.
  [[nodiscard]] static std::unique_ptr<TestMqttPublisher> connect(std::uint16_t port,
                                                                  const std::string& username = "",
                                                                  const std::string& password = "");
  ~TestMqttPublisher();
  TestMqttPublisher(const TestMqttPublisher&) = delete;
  TestMqttPublisher& operator=(const TestMqttPublisher&) = delete;

  // Publishes and waits for the broker's PUBACK; false (and a test failure) otherwise. A request
  // names its `responseTopic` and `correlationData` (MQTT 5 properties) when they are not empty.
  bool publish(const std::string& topic, const std::string& payload, bool retain = false,
               const std::string& responseTopic = "", const std::string& correlationData = "");

  // Subscribes to `controlTopic` (waits for the SUBACK) and answers each control from then on.
  bool answerControls(const std::string& controlTopic);

  // What arrived on a subscribed topic (a control, or a reply to this client's request).
  struct ReceivedControl {
    std::string topic;
    std::string payload;            // the bytes as received
    stream::ClientMessage message;  // the payload parsed as a control (when it is one)
    std::string responseTopic;
    std::string correlationData;
  };
  [[nodiscard]] bool waitForControls(std::size_t count, std::chrono::milliseconds timeout) const;
  [[nodiscard]] std::vector<ReceivedControl> controls() const;

 private:
  TestMqttPublisher();
  struct Callbacks;

  mosquitto* client_ = nullptr;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  bool connected_ = false;
  int connackCode_ = -1;
  std::set<int> done_;  // message ids of publishes that left and of SUBACKs
  std::vector<ReceivedControl> controls_;
};

}  // namespace vem::testing
