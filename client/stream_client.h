// StreamClient: receives a vemd stream (proto/vem_stream.proto, docs/protocol.md) for a render
// client, through one of two transports chosen by the URL's scheme:
// - ws:// or wss://: straight to vemd over WebSocket (websocket_transport.h): the bearer token,
//   subscribe after the daemon's Hello, a refused message closes the connection (1002);
// - mqtt:// or mqtts://: through an MQTT 5 broker (mqtt_transport.h, mqtt_url.h; docs/protocol.md,
//   "MQTT"): user name and password, client certificates, the camera's hello, lights, status and
//   (when asked for) cubemap topics; a refused payload is counted and the client stays subscribed;
//   control messages go to the camera's control topic and the broker's ACL decides.
// Either way every message is decoded and validated (server_message_decoder.h), the newest light
// frame and environment frame are kept with their receipt time, the client reconnects after an
// exponential backoff (util/backoff.h) when a connection fails or drops, and it stops for good, in
// state Refused with one sentence, when the peer speaks another protocol major or refuses the
// credentials (the token: HTTP 401 or 403; the broker: CONNACK 134 or 135).
//
// Threads: the client runs its own network thread. Every public member is thread-safe and none
// waits on the network. The callbacks in StreamClientOptions run on the network thread, one at a
// time, and must not block for long (they hold up reception) nor call stop(). Times: receivedAt on
// the steady clock (ages), receivedUnixNs on CLOCK_REALTIME (latency to the daemon's
// publish_unix_ns).
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
  Connected,   // WebSocket: the daemon's Hello arrived; MQTT: the broker accepted the subscriptions
  Waiting,     // the last attempt failed or the connection dropped; retrying after the backoff
  Refused,     // stopped for good: another protocol major, or the credentials refused (see reason)
  Stopped,     // stop() was called
};

[[nodiscard]] std::string_view connectionStateName(ConnectionState state);

// What this connection asks for (vem.stream.Subscribe); 0 means the daemon's default. Over MQTT
// the camera's vemd publishes what its configuration says: the client subscribes to the lights
// topic when `lights`, to the cubemap topic when cubemapRateHz > 0; the other fields do not apply.
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
  // ws://HOST[:PORT][/PATH] or wss://... (stream_url.h); mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA or
  // mqtts://... (mqtt_url.h)
  std::string url;
  std::string token;  // WebSocket: empty for none (then no control messages)
  Subscription subscription;
  // wss://, mqtts://: trust the CA certificates of this PEM file instead of the system's
  std::string caFile;
  // MQTT: the broker's user name (else the URL's USER@, else none) and password (values: a tool
  // reads them from a private file); a client certificate and its key (PEM files, mqtts:// only)
  std::string username;
  std::string password;
  std::string certFile;
  std::string keyFile;
  std::chrono::milliseconds initialBackoff{100};
  std::chrono::milliseconds maxBackoff{5000};
  // TCP connect and the TLS handshake, then the WebSocket handshake or the broker's CONNACK
  std::chrono::milliseconds connectTimeout{5000};
  std::size_t latencyWindow = 1000;  // light frames in the latency summary
  // Called on the network thread for each accepted frame and each change of state.
  std::function<void(const Received<LightFrame>&)> onLightFrame;
  std::function<void(const Received<EnvironmentFrame>&)> onEnvironmentFrame;
  std::function<void(ConnectionState, const std::string& reason)> onStateChange;
};

struct ClientStats {
  std::uint64_t received = 0;           // light frames accepted
  std::uint64_t skipped = 0;            // seq gaps between received light frames
  std::uint64_t environmentFrames = 0;  // environment frames accepted
  std::uint64_t decodeErrors = 0;       // messages refused (WebSocket: each closed its connection)
  std::uint64_t reconnects = 0;         // connections established after the first
  LatencySummary latency;               // publish_unix_ns to receipt
};

// The daemon's answer to a control message, or why there is none (one sentence).
using ControlResult = std::expected<ControlReply, std::string>;

class StreamClient {
 public:
  // Checks the options (URL, CA file, MQTT credentials and certificates) and starts connecting on
  // the client's own thread; an error sentence when the options are unusable.
  [[nodiscard]] static std::expected<std::unique_ptr<StreamClient>, std::string> start(
      StreamClientOptions options);
  ~StreamClient();
  StreamClient(const StreamClient&) = delete;
  StreamClient& operator=(const StreamClient&) = delete;

  // Closes the connection politely (WebSocket: a closing handshake, code 1000; MQTT: DISCONNECT;
  // the socket is dropped if the peer does not answer within 1 s) and joins the network thread;
  // pending controls fail. Idempotent.
  void stop();

  [[nodiscard]] ConnectionState state() const;
  [[nodiscard]] std::string stateReason() const;  // why the last connection ended or was refused
  // WebSocket: the current (or last) connection's; MQTT: the camera's retained one, when it came
  [[nodiscard]] std::optional<Hello> hello() const;
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

  // Sends a control message; the future holds the daemon's reply, or why there is none.
  // WebSocket: needs the token and a connection whose Hello allowed control. MQTT: needs a
  // connection; the broker's ACL decides ("the broker refused the control message: not
  // authorized").
  [[nodiscard]] std::future<ControlResult> sendControl(const stream::Control& control);

 private:
  struct Impl;
  explicit StreamClient(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::client
