// StreamClient: receives a vemd stream (proto/vem_stream.proto, docs/protocol.md) for a render
// client. It connects to ws:// or wss:// (TLS through OpenSSL, the peer verified against the
// system's CAs or a given CA file, and its host name), sends `Authorization: Bearer TOKEN` when it
// has a token, subscribes after the daemon's Hello, decodes and validates every message
// (server_message_decoder.h) and keeps the newest light frame and environment frame with their
// receipt time. When the connection fails or drops, or a message is refused (the connection is
// closed with status 1002 and the reason), it reconnects after an exponential backoff (backoff.h);
// it stops for good, in state Refused with one sentence, when the daemon speaks another protocol
// major or refuses the token (HTTP 401 or 403).
//
// Threads: the client runs its own I/O thread. Every public member is thread-safe. The callbacks
// in StreamClientOptions run on the I/O thread, one at a time, and must not block for long (they
// hold up reception) nor call stop(). Times: receivedAt on the steady clock (ages),
// receivedUnixNs on CLOCK_REALTIME (latency to the daemon's publish_unix_ns).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "client/reception_stats.h"
#include "client/stream_events.h"
#include "proto/vem_stream.pb.h"

namespace vem::client {

enum class ConnectionState {
  Connecting,  // resolving, connecting, handshaking
  Connected,   // the daemon's Hello arrived; frames flow
  Waiting,     // the last attempt failed or the connection dropped; retrying after the backoff
  Refused,     // stopped for good: another protocol major, or the token refused (see reason)
  Stopped,     // stop() was called
};

[[nodiscard]] std::string_view connectionStateName(ConnectionState state);

// What this connection asks for (vem.stream.Subscribe); 0 means the daemon's default.
struct Subscription {
  bool lights = true;
  double cubemapRateHz = 0.0;  // 0: no environment frames
  std::uint32_t cubemapFacePx = 0;
  std::uint32_t cubemapLevels = 0;
  bool preview = false;
};

template <class Frame>
struct Received {
  Frame frame;
  std::chrono::steady_clock::time_point receivedAt;
  std::int64_t receivedUnixNs = 0;
  [[nodiscard]] std::chrono::nanoseconds age() const {
    return std::chrono::steady_clock::now() - receivedAt;
  }
};

struct StreamClientOptions {
  std::string url;    // ws://HOST[:PORT][/PATH] or wss://... (stream_url.h)
  std::string token;  // empty: none (then no control messages)
  Subscription subscription;
  std::string caFile;  // wss: trust the CA certificates of this PEM file instead of the system's
  std::chrono::milliseconds initialBackoff{100};
  std::chrono::milliseconds maxBackoff{5000};
  std::chrono::milliseconds connectTimeout{5000};  // TCP connect, TLS and WebSocket handshakes
  std::size_t latencyWindow = 1000;                // light frames in the latency summary
  // Called on the I/O thread for each accepted frame and each change of state.
  std::function<void(const Received<LightFrame>&)> onLightFrame;
  std::function<void(const Received<EnvironmentFrame>&)> onEnvironmentFrame;
  std::function<void(ConnectionState, const std::string& reason)> onStateChange;
};

struct ClientStats {
  std::uint64_t received = 0;           // light frames accepted
  std::uint64_t skipped = 0;            // seq gaps between received light frames
  std::uint64_t environmentFrames = 0;  // environment frames accepted
  std::uint64_t decodeErrors = 0;       // messages refused (each closed its connection)
  std::uint64_t reconnects = 0;         // connections established after the first
  LatencySummary latency;               // publish_unix_ns to receipt
};

// The daemon's answer to a control message, or why there is none (one sentence).
using ControlResult = std::expected<ControlReply, std::string>;

class StreamClient {
 public:
  // Checks the options (URL, CA file) and starts connecting on the client's own thread; an error
  // sentence when the options are unusable.
  [[nodiscard]] static std::expected<std::unique_ptr<StreamClient>, std::string> start(
      StreamClientOptions options);
  ~StreamClient();
  StreamClient(const StreamClient&) = delete;
  StreamClient& operator=(const StreamClient&) = delete;

  // Closes the connection with a WebSocket closing handshake (code 1000; the socket is dropped if
  // the daemon does not answer within 1 s) and joins the I/O thread; pending controls fail.
  // Idempotent.
  void stop();

  [[nodiscard]] ConnectionState state() const;
  [[nodiscard]] std::string stateReason() const;  // why the last connection ended or was refused
  [[nodiscard]] std::optional<Hello> hello() const;    // the current (or last) connection's
  [[nodiscard]] std::optional<Status> status() const;  // the newest
  [[nodiscard]] std::optional<Received<LightFrame>> latestLightFrame() const;
  [[nodiscard]] std::optional<Received<EnvironmentFrame>> latestEnvironmentFrame() const;
  [[nodiscard]] ClientStats stats() const;

  // Waits until the newest light frame has a seq above `afterSeq` (any frame when empty) and
  // returns it; empty after `timeout` or once the client is Refused or Stopped.
  [[nodiscard]] std::optional<Received<LightFrame>> waitForLightFrame(
      std::optional<std::uint64_t> afterSeq, std::chrono::milliseconds timeout) const;
  // Waits until the state is `state`; false after `timeout`.
  [[nodiscard]] bool waitForState(ConnectionState state, std::chrono::milliseconds timeout) const;

  // Sends a control message (needs the token and a connection whose Hello allowed control); the
  // future holds the daemon's reply, or why there is none.
  [[nodiscard]] std::future<ControlResult> sendControl(const stream::Control& control);

 private:
  struct Impl;
  explicit StreamClient(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::client
