// StreamServer: vemd's WebSocket server (Boost.Beast over Asio, optionally TLS through OpenSSL)
// that streams light frames, environment frames and statuses to render clients and takes their
// subscriptions and control messages (proto/vem_stream.proto, docs/protocol.md).
//
// Threads and ownership:
// - The server owns one io_context and the one thread that runs it; every connection lives on
//   that thread. start() binds and starts it; the destructor stops it and joins.
// - The processing thread publishes through publishLights / publishEnvironment / publishStatus:
//   each stores the newest message in a mutex-guarded slot and posts at most one fan-out to the
//   io thread, so publishing never waits for a client and the io thread's queue stays bounded.
//   A message is serialized once and shared by all connections.
// - Each connection keeps newest-only slots (outbox.h): a client that stops reading keeps one
//   write pending, its slots keep being replaced (skips counted for it) and nothing else slows;
//   a write pending longer than sendTimeout closes that connection.
// - Control messages go into a mutex-guarded inbox that the processing thread drains between
//   frames (takeControls); the answers come back through reply().
//
// Security: handshake_auth.h decides each upgrade request (401 when refused); connections beyond
// maxClients get 503; client messages larger than kMaxClientMessageBytes close that connection
// (1009); client_message_handler.h decides everything else a client sends.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "proto/vem_stream.pb.h"
#include "stream/cubemap_demand.h"
#include "stream/outbox.h"
#include "stream/subscription.h"

namespace vem::stream {

struct StreamServerOptions {
  std::string address = "127.0.0.1";  // an IPv4 or IPv6 address to listen on
  std::uint16_t port = 8765;          // 0: an ephemeral port (boundPort() tells which)
  std::string token;                  // "": none (control is then refused to everyone)
  bool tokenRequiredToConnect = false;  // set for listeners beyond loopback
  std::string tlsCertFile;            // PEM; with tlsKeyFile: wss:// instead of ws://
  std::string tlsKeyFile;
  std::size_t maxClients = 64;
  std::chrono::milliseconds sendTimeout{10'000};       // a write pending longer closes the client
  std::chrono::milliseconds handshakeTimeout{10'000};  // TLS + HTTP upgrade
  std::chrono::milliseconds idleTimeout{30'000};       // pings after half; no answer: closed
  std::size_t maxPendingControls = 64;
  Hello hello;  // server, source, calibration_id, max_lights; the rest is set per connection
};

struct PendingControl {
  std::uint64_t connection = 0;
  std::uint64_t requestId = 0;
  Control command;
};

struct ServerCounters {
  std::size_t clients = 0;                 // open WebSocket connections now
  std::uint64_t accepted = 0;              // WebSocket connections opened so far
  std::uint64_t refusedUnauthorized = 0;   // 401
  std::uint64_t refusedFull = 0;           // 503
  std::uint64_t closedByServer = 0;        // closed for a bad message, a timeout, ...
  std::uint64_t controlsReceived = 0;      // control messages put into the inbox
  std::uint64_t lightsPublished = 0;       // publishLights calls
  std::uint64_t lightsSkipped = 0;         // over all connections, closed ones included
};

class StreamServer {
 public:
  // Binds and starts listening; one sentence when the address, the port or the TLS files fail.
  [[nodiscard]] static std::expected<std::unique_ptr<StreamServer>, std::string> start(
      StreamServerOptions options);
  ~StreamServer();
  StreamServer(const StreamServer&) = delete;
  StreamServer& operator=(const StreamServer&) = delete;

  [[nodiscard]] std::uint16_t boundPort() const;
  [[nodiscard]] bool tls() const;
  // "ws://127.0.0.1:8765" or "wss://...".
  [[nodiscard]] std::string url() const;

  // --- any thread (the processing thread); none of these waits for a client ---
  // A serialized ServerMessage with a LightFrame, for connections subscribed to lights.
  void publishLights(SharedBytes message);
  // A serialized environment frame of `variant`, for connections subscribed to it whose rate
  // allows one now.
  void publishEnvironment(const CubeVariant& variant, SharedBytes message);
  // A status for every connection; clients and skipped_for_you are filled in per connection.
  void publishStatus(const Status& status);
  [[nodiscard]] CubemapDemand cubemapDemand() const;
  [[nodiscard]] std::vector<PendingControl> takeControls();
  void reply(std::uint64_t connection, const ControlReply& reply);
  [[nodiscard]] ServerCounters counters() const;

  class Impl;

 private:
  explicit StreamServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::stream
