// RawWsClient: a bare WebSocket client of vemd's stream (Boost.Beast over TCP, 127.0.0.1 only) for
// the stream server's tests (through WsTestClient), the end-to-end tests and the stream benchmark,
// where StreamClient is too polite: it can ask for any path, connect from another loopback
// address, send bytes that are no ClientMessage, as text or binary, shrink
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
  std::string target = "/";                   // the request's path
  std::string source;  // the local address to connect from ("": any; 127.0.0.2 is another host)
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
  // The Hello the daemon sent first (empty before a connect that returned 0).
  [[nodiscard]] const stream::ServerMessage& hello() const { return hello_; }
  // Sends `message` (its protocol version set to this build's when 0); false when the write
  // failed or timed out.
  [[nodiscard]] bool send(stream::ClientMessage message, std::chrono::milliseconds timeout);
  // Sends `bytes` as one binary (or text) message, whatever they hold.
  [[nodiscard]] bool sendBytes(const std::string& bytes, bool binary, std::chrono::milliseconds timeout);
  // The next message's bytes (one serialized ServerMessage); empty when the connection ended or
  // nothing came within `timeout`.
  [[nodiscard]] std::optional<std::string> readBytes(std::chrono::milliseconds timeout);
  // Closes with a close frame (code 1000, `reason` in it; bounded by `timeout`), or drops the TCP
  // connection at once.
  void close(std::chrono::milliseconds timeout, const std::string& reason = {});
  void drop();

  // The daemon's close frame, once a read ended on it (code 0: none came).
  [[nodiscard]] int closeCode() const;
  [[nodiscard]] std::string closeReason() const;
  // Why the last operation failed ("timed out" when it was given up; "" when it succeeded).
  [[nodiscard]] const std::string& lastError() const { return lastError_; }

 private:
  template <class Start>
  bool run(Start start, std::chrono::milliseconds timeout);

  boost::asio::io_context ioc_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
  boost::beast::flat_buffer buffer_;
  stream::ServerMessage hello_;
  std::string lastError_;
};

}  // namespace vem::e2e
