// WsSubscriberSet: N WebSocket clients of vemd's own stream on 127.0.0.1, each its own connection,
// each subscribed to light frames (a new connection is), reading every message: the direct path
// the MQTT fan-out is compared with. Like MqttSubscriberSet they are driven by a few threads (one
// io_context, Boost.Beast's asynchronous WebSocket stream, a strand per client; Beast answers
// vemd's pings), not one thread each, so the bench costs the same on both paths.
//
// start() returns once every client finished its opening handshake (bounded by `timeout`), or one
// sentence saying how many did. Each message is handed to `onMessage` on one of the threads with
// the time its read ended, CLOCK_REALTIME ns. stop() (and the destructor) stops the threads and
// drops the connections; `onMessage` is not called after it returns.
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

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

namespace vem::bench {

// Client index, payload (one serialized ServerMessage), receipt time (CLOCK_REALTIME ns).
using WsMessageHandler = std::function<void(std::size_t, std::string_view, std::int64_t)>;

struct WsSubscriberOptions {
  std::uint16_t port = 0;  // vemd's stream, on 127.0.0.1
  std::size_t clients = 1;
  std::size_t threads = 2;
  std::chrono::milliseconds timeout{60'000};  // for all of them to connect
  WsMessageHandler onMessage;
};

class WsSubscriberSet {
 public:
  [[nodiscard]] static std::expected<std::unique_ptr<WsSubscriberSet>, std::string> start(
      WsSubscriberOptions options);
  ~WsSubscriberSet();
  WsSubscriberSet(const WsSubscriberSet&) = delete;
  WsSubscriberSet& operator=(const WsSubscriberSet&) = delete;

  void stop();
  // Clients whose connection ended before stop() (vemd closed it, an error).
  [[nodiscard]] std::size_t lost() const { return lost_.load(); }

  struct Client;

 private:
  explicit WsSubscriberSet(WsSubscriberOptions options);
  void connect(Client& client);
  void read(Client& client);

  WsSubscriberOptions options_;
  boost::asio::io_context ioc_;
  boost::asio::executor_work_guard<boost::asio::io_context::executor_type> work_;
  std::vector<std::unique_ptr<Client>> clients_;  // destroyed before ioc_
  std::vector<std::thread> threads_;
  std::atomic<bool> stopping_{false};
  std::atomic<std::size_t> connected_{0};
  std::atomic<std::size_t> failed_{0};
  std::atomic<std::size_t> lost_{0};
  bool stopped_ = false;
};

}  // namespace vem::bench
