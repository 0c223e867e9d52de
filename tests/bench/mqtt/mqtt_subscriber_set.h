// MqttSubscriberSet: N MQTT 5 subscribers of a broker on 127.0.0.1, each its own libmosquitto
// client with its own TCP connection, clean session, QoS 0 subscription to one topic filter.
// They are driven by a few threads (not one thread each) that wait on their share of the sockets
// with epoll and let libmosquitto read (mosquitto_loop_read / _write / _misc): 500 subscribers cost
// the bench two threads, so the cores it shares with vemd and the broker go to reading messages.
//
// start() returns once every subscriber holds its SUBACK (bounded by `timeout`), or one sentence
// saying how many did. Each message is handed to `onMessage` on its subscriber's thread (one
// subscriber is always on the same thread) with the time it was read, CLOCK_REALTIME ns, taken
// before anything else is done with it. stop() (and the destructor) ends the threads, sends each
// client's DISCONNECT and frees them; `onMessage` is not called after it returns.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "util/unique_fd.h"

namespace vem::bench {

// Subscriber index, topic, payload, receipt time (CLOCK_REALTIME ns).
using MqttMessageHandler =
    std::function<void(std::size_t, std::string_view, std::string_view, std::int64_t)>;

struct MqttSubscriberOptions {
  std::uint16_t port = 1883;        // the broker's, on 127.0.0.1
  std::vector<std::string> topics;  // one topic filter per subscriber: N = topics.size()
  std::string clientIdPrefix = "vem-mqtt-bench";
  std::size_t threads = 2;
  std::chrono::milliseconds timeout{60'000};  // for all of them to connect and subscribe
  MqttMessageHandler onMessage;
};

class MqttSubscriberSet {
 public:
  [[nodiscard]] static std::expected<std::unique_ptr<MqttSubscriberSet>, std::string> start(
      MqttSubscriberOptions options);
  ~MqttSubscriberSet();
  MqttSubscriberSet(const MqttSubscriberSet&) = delete;
  MqttSubscriberSet& operator=(const MqttSubscriberSet&) = delete;

  void stop();
  // Subscribers whose connection ended before stop() (the broker closed it, an error).
  [[nodiscard]] std::size_t lost() const { return lost_.load(); }

  struct Subscriber;

 private:
  explicit MqttSubscriberSet(MqttSubscriberOptions options);
  void run(std::size_t thread);
  void lose(Subscriber& subscriber);

  MqttSubscriberOptions options_;
  std::vector<std::unique_ptr<Subscriber>> subscribers_;
  std::vector<util::UniqueFd> epollFds_;  // one per thread
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  std::atomic<std::size_t> subscribed_{0};
  std::atomic<std::size_t> lost_{0};
  bool stopped_ = false;
};

}  // namespace vem::bench
