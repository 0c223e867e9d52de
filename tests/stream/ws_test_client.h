// A WebSocket client for the stream server's tests (127.0.0.1 only): connects with an optional
// bearer token, reads ServerMessages, sends ClientMessages or raw bytes. Every operation gives up
// after kGiveUpAfter (so a broken server fails a test instead of hanging it; never a timing
// assertion). One client per thread. It is the end-to-end tests' RawWsClient (compiled once, in
// vem_test_vemd_child) with a fixed time-out and the messages parsed; no Boost.Beast in here, so
// that the tests that include it compile in seconds.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>

#include "proto/stream_protocol.h"
#include "proto/vem_stream.pb.h"
#include "stream_e2e/raw_ws_client.h"

namespace vem::testing {

inline constexpr std::chrono::seconds kGiveUpAfter{20};

class WsTestClient {
 public:
  // 0 when upgraded and the Hello read (the server then counts this client as open), else the
  // HTTP status of the refusal (-1: no answer, or no Hello first).
  // `source`: the local address to connect from (another loopback address, 127.0.0.2, makes the
  // server see another client host).
  int connect(std::uint16_t port, const std::string& target = "/",
              const std::optional<std::string>& bearer = std::nullopt,
              const std::string& source = "") {
    e2e::RawConnectOptions options;
    options.token = bearer;
    options.timeout = kGiveUpAfter;
    options.target = target;
    options.source = source;
    return raw_.connect(port, options);
  }

  [[nodiscard]] const stream::ServerMessage& hello() const { return raw_.hello(); }

  // The next message, or nullopt when the connection ended (closeCode() tells how).
  std::optional<stream::ServerMessage> read() {
    const auto bytes = raw_.readBytes(kGiveUpAfter);
    stream::ServerMessage message;
    if (!bytes || !message.ParseFromString(*bytes)) return std::nullopt;
    return message;
  }

  // The next light frame's seq, skipping other messages; nullopt when the connection ended.
  std::optional<std::uint64_t> nextLightsSeq(int* environments = nullptr) {
    for (;;) {
      auto message = read();
      if (!message) return std::nullopt;
      if (message->has_lights()) return message->lights().seq();
      if (message->has_environment() && environments != nullptr) ++*environments;
    }
  }

  // The next reply, skipping other messages.
  std::optional<stream::ControlReply> nextReply() {
    for (;;) {
      auto message = read();
      if (!message) return std::nullopt;
      if (message->has_reply()) return message->reply();
    }
  }

  bool send(const stream::ClientMessage& message) { return raw_.send(message, kGiveUpAfter); }
  bool sendRaw(const std::string& bytes, bool binary = true) {
    return raw_.sendBytes(bytes, binary, kGiveUpAfter);
  }

  // The server's close code once read() returned nullopt after a close frame (0: none).
  [[nodiscard]] int closeCode() const { return raw_.closeCode(); }
  [[nodiscard]] std::string closeReason() const { return raw_.closeReason(); }
  // Why the last operation failed ("": it did not).
  [[nodiscard]] const std::string& error() const { return raw_.lastError(); }

  void close() { raw_.close(kGiveUpAfter); }
  // A normal close (1000) with `reason` in the close frame.
  void closeWith(const std::string& reason) { raw_.close(kGiveUpAfter, reason); }
  void drop() { raw_.drop(); }

 private:
  e2e::RawWsClient raw_;
};

// Waits (boundedly, 20 s) until `ready` holds; the bound only keeps a broken server from hanging.
template <class Ready>
bool eventually(Ready ready) {
  for (int i = 0; i < 4000; ++i) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace vem::testing
