// StreamServer: vemd's WebSocket server (Boost.Beast over Asio, optionally TLS through OpenSSL)
// that streams light frames, environment frames and statuses to render clients and takes their
// subscriptions and control messages (proto/vem_stream.proto, docs/protocol.md).
//
// Threads and ownership:
// - The server owns one io_context and the one thread that runs it (at nice 5:
//   thread_niceness.h); every connection lives on that thread. start() binds and starts it; the
//   destructor stops it and joins.
// - The processing thread publishes through publishLights / publishEnvironment / publishStatus:
//   each stores the newest message in a mutex-guarded slot and posts at most one fan-out to the
//   io thread, so publishing never waits for a client and the io thread's queue stays bounded.
//   A message is serialized once and shared by all connections.
// - Each connection keeps newest-only slots (outbox.h) and is paced by probe pings
//   (client_lag.h): while a client is behind, its slots keep being replaced (skips counted for
//   it) and nothing else slows; a client more than maxClientLag behind, or a write pending
//   longer than sendTimeout, closes that connection. Each socket's kernel send buffer is
//   sendBufferBytes.
// - Control messages go into a mutex-guarded inbox that the processing thread drains between
//   frames (takeControls); the answers come back through reply().
//
// Security: handshake_auth.h decides each upgrade request (401 when refused); connections beyond
// maxClients get 503; client messages larger than kMaxClientMessageBytes close that connection
// (1009); client_message_handler.h decides everything else a client sends, with the read-only
// clients' cube-map budget.
//
// Floods (issue 16): the opening handshake (TLS and the upgrade request) must end within
// handshakeTimeout; at most maxHandshakes are pending, maxHandshakesPerAddress from one address
// (handshake_slots.h: over that, 503 at once; all slots taken, the heaviest address's oldest is
// evicted). Sockets beyond what the descriptor limit allows are closed unanswered, counted.
// Connections, departures, refusals and failed handshakes are logged one by one up to a budget per
// 10 s (log_budget.h), then as counts; outside text in the log goes through util::printable.
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
#include "stream/publisher.h"
#include "stream/subscription.h"

namespace vem::stream {

struct StreamServerOptions {
  std::string address = "127.0.0.1";    // an IPv4 or IPv6 address to listen on
  std::uint16_t port = 8765;            // 0: an ephemeral port (boundPort() tells which)
  std::string token;                    // "": none (control is then refused to everyone)
  bool tokenRequiredToConnect = false;  // set for listeners beyond loopback
  std::string tlsCertFile;              // PEM; with tlsKeyFile: wss:// instead of ws://
  std::string tlsKeyFile;
  std::size_t maxClients = 64;
  std::size_t maxHandshakes = 128;                // connections in their opening handshake at most
  std::size_t maxHandshakesPerAddress = 32;       // of those, from one address
  std::chrono::milliseconds sendTimeout{10'000};  // a write pending longer closes the client
  std::chrono::milliseconds handshakeTimeout{3'000};  // TLS + HTTP upgrade
  std::chrono::milliseconds idleTimeout{30'000};      // pings after half; no answer: closed
  std::chrono::milliseconds maxClientLag{5'000};      // a client further behind is closed (1008)
  std::chrono::milliseconds lagSlack{100};            // behind by round trip + this: held
  int sendBufferBytes = 256 * 1024;                   // SO_SNDBUF of each client's socket
  CubemapBudget cubemapBudget;                        // for clients without the token
  std::size_t maxPendingControls = 64;
  Hello hello;  // server, source, calibration_id, max_lights; the rest is set per connection
};

struct ServerCounters {
  std::size_t clients = 0;                // open WebSocket connections now
  std::size_t handshakes = 0;             // connections in their opening handshake now
  std::uint64_t accepted = 0;             // WebSocket connections opened so far
  std::uint64_t refusedBadRequest = 0;    // 400
  std::uint64_t refusedUnauthorized = 0;  // 401
  std::uint64_t refusedFull = 0;          // 503: maxClients open
  std::uint64_t refusedBusyAddress = 0;   // 503: maxHandshakesPerAddress pending from its address
  std::uint64_t handshakesTimedOut = 0;   // no complete request within handshakeTimeout
  std::uint64_t handshakesFailed = 0;     // TLS failed, a malformed request, the client left
  std::uint64_t handshakesEvicted = 0;    // closed to make room (maxHandshakes pending)
  std::uint64_t closedUnanswered = 0;     // over the descriptor budget: closed at once
  std::uint64_t closedByServer = 0;       // closed for a bad message, a timeout, ...
  std::uint64_t closedTooSlow = 0;        // more than maxClientLag behind: being closed
  std::uint64_t controlsReceived = 0;     // control messages put into the inbox
  std::uint64_t lightsPublished = 0;      // publishLights calls
  std::uint64_t lightsSkipped = 0;        // over all connections, closed ones included
};

class StreamServer final : public Publisher {
 public:
  // Binds and starts listening; one sentence when the address, the port, the TLS files or the
  // descriptor limit (maxClients + maxHandshakes sockets) fail. Raises the soft RLIMIT_NOFILE to
  // the hard one (at most 65536).
  [[nodiscard]] static std::expected<std::unique_ptr<StreamServer>, std::string> start(
      StreamServerOptions options);
  ~StreamServer() override;
  StreamServer(const StreamServer&) = delete;
  StreamServer& operator=(const StreamServer&) = delete;

  [[nodiscard]] std::uint16_t boundPort() const;
  [[nodiscard]] bool tls() const;
  // "ws://127.0.0.1:8765" or "wss://...".
  [[nodiscard]] std::string url() const;

  // --- any thread (the processing thread); none of these waits for a client ---
  // A serialized ServerMessage with a LightFrame, for connections subscribed to lights.
  void publishLights(SharedBytes message) override;
  // A serialized environment frame of `variant`, for connections subscribed to it whose rate
  // allows one now.
  void publishEnvironment(const CubeVariant& variant, SharedBytes message) override;
  // A status for every connection; clients and skipped_for_you are filled in per connection.
  void publishStatus(const Status& status) override;
  [[nodiscard]] CubemapDemand cubemapDemand() const override;
  [[nodiscard]] std::vector<PendingControl> takeControls() override;
  void reply(std::uint64_t connection, const ControlReply& reply) override;
  [[nodiscard]] ServerCounters counters() const;

  class Impl;

 private:
  explicit StreamServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::stream
