// RawWsClient: a bare WebSocket client of vemd's stream (Boost.Beast over TCP, 127.0.0.1 only) for
// the end-to-end tests and the stream benchmark, where StreamClient is too polite: it can shrink
// its socket's receive buffer (SO_RCVBUF, set before connecting so the TCP window stays small),
// subscribe and then never read (a stalled client that makes the daemon's writes back up), read
// raw messages to measure their serialized size, or drop the connection without a close frame.
//
// Every operation gives up after the timeout it is given (the socket is then dropped), so a broken
// daemon fails a test instead of hanging it. One client per thread; each owns its io_context.
// Sizes in bytes.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>

#include "proto/vem_stream.pb.h"

namespace vem::e2e {

struct RawConnectOptions {
  std::optional<std::string> token;           // sent as "Authorization: Bearer T"
  std::optional<int> receiveBufferBytes;      // SO_RCVBUF before connecting (the kernel doubles it)
  std::chrono::milliseconds timeout{20'000};  // TCP connect, handshake and the Hello
};

class RawWsClient {
 public:
  RawWsClient();
  ~RawWsClient();
  RawWsClient(const RawWsClient&) = delete;
  RawWsClient& operator=(const RawWsClient&) = delete;

  // 0 when upgraded and the daemon's Hello read; else the HTTP status of the refusal, or -1 (no
  // answer, no Hello, a timeout).
  [[nodiscard]] int connect(std::uint16_t port, const RawConnectOptions& options = {});
  // Sends `message` (its protocol version set to this build's when 0); false when the write
  // failed or timed out.
  [[nodiscard]] bool send(stream::ClientMessage message, std::chrono::milliseconds timeout);
  // The next message's bytes (one serialized ServerMessage); empty when the connection ended or
  // nothing came within `timeout`.
  [[nodiscard]] std::optional<std::string> readBytes(std::chrono::milliseconds timeout);
  // Closes with a close frame (bounded by `timeout`), or drops the TCP connection at once.
  void close(std::chrono::milliseconds timeout);
  void drop();

 private:
  template <class Start>
  bool run(Start start, std::chrono::milliseconds timeout);

  boost::asio::io_context ioc_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
  boost::beast::flat_buffer buffer_;
};

}  // namespace vem::e2e
