// TestStreamServer: a small WebSocket server for the client's tests (not production code: vemd's
// server is daemon/stream/). It listens on 127.0.0.1 (an ephemeral port, or a given one to stand
// for a restarted daemon), checks `Authorization: Bearer TOKEN` when given a token (401 otherwise),
// greets each connection with a Hello (or any bytes set with setGreeting), sends what the test
// passes to send(), records the handshakes' Authorization headers, the client messages and how
// each connection ended, and answers each Control with an ok ControlReply. Its own I/O thread; members are thread-safe.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "proto/vem_stream.pb.h"

namespace vem::client::test {

class TestStreamServer {
 public:
  explicit TestStreamServer(std::uint16_t port = 0, std::string requiredToken = "",
                            std::string greeting = "");  // "": a Hello of major 1
  ~TestStreamServer();  // drops every connection at once (no close frame), like a dying daemon

  [[nodiscard]] std::uint16_t port() const { return port_; }
  [[nodiscard]] std::string url() const;

  // Sends `bytes` as one binary message to every open connection.
  void send(const std::string& bytes);

  [[nodiscard]] bool waitForConnections(std::size_t count, std::chrono::milliseconds timeout) const;
  [[nodiscard]] bool waitForClientMessages(std::size_t count,
                                           std::chrono::milliseconds timeout) const;
  [[nodiscard]] bool waitForEndings(std::size_t count, std::chrono::milliseconds timeout) const;
  [[nodiscard]] std::vector<std::string> authorizations() const;
  // How each accepted WebSocket connection ended, in order: "close CODE" after a closing
  // handshake the client began, "dropped (WHY)" when the connection just broke.
  [[nodiscard]] std::vector<std::string> endings() const;
  [[nodiscard]] std::vector<stream::ClientMessage> clientMessages() const;

 private:
  struct State;
  std::shared_ptr<State> state_;
  std::uint16_t port_ = 0;
};

}  // namespace vem::client::test
