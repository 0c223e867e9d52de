// ClientState: what a StreamClient knows and counts, whichever transport carries the stream
// (websocket_transport.h, mqtt_transport.h): the connection state and its reason, the newest
// Hello, Status, light frame and environment frame with their receipt times, the reception
// statistics and counters, and the control messages waiting for their reply.
//
// The transport calls the "transport side" from its network thread, one call at a time; the
// StreamClient's callers read through the "caller side" from any thread. Every member is
// thread-safe: one mutex guards the values, and the user's callbacks (StreamClientOptions) run on
// the transport's thread outside it. Once stopped, changes of state are ignored (stop() owns the
// last one, Stopped). Times: receivedAt on the steady clock, receivedUnixNs on CLOCK_REALTIME.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "client/reception_stats.h"
#include "client/stream_client.h"
#include "client/stream_events.h"

namespace vem::client {

class ClientState {
 public:
  // Borrows `options` (the url for the log, the latency window, the callbacks): it must outlive
  // this.
  explicit ClientState(const StreamClientOptions& options);

  // ---- transport side (its network thread)

  // Records the state and its reason, wakes the waiters, logs one line per change (a retry failing
  // again for the same reason is not logged again) and calls onStateChange. Ignored once stopped.
  void setState(ConnectionState next, std::string why);
  void keepHello(Hello hello);
  // A connection was established: the second and later ones count as reconnects.
  void countConnection();
  void countDecodeError();
  void onLightFrame(LightFrame frame);
  void onEnvironmentFrame(EnvironmentFrame frame);
  void onStatus(Status status);
  // Fulfils the pending control with the reply's request id; false when none waits for it.
  bool onControlReply(ControlReply reply);

  // Keeps `promise` until its reply and returns the request id to send it with; while stopped or
  // refused (or, with needConnected, in any state but Connected), sets the promise to `notLive`
  // instead and returns nothing. Checked and kept under one lock: a transport that changes the
  // state before it fails the pending controls fails every control it accepted.
  [[nodiscard]] std::optional<std::uint64_t> addPendingControl(std::promise<ControlResult> promise,
                                                               const std::string& notLive,
                                                               bool needConnected = false);
  void failPendingControl(std::uint64_t requestId, const std::string& why);
  void failPendingControls(const std::string& why);
  // A request id for a message that is not a control (a WebSocket Subscribe).
  [[nodiscard]] std::uint64_t nextRequestId();

  // Runs `f` under the lock when the client is neither stopped nor refused (a transport posting
  // work that stop() must not race); false otherwise. `f` must not call back into this object.
  template <class F>
  bool whileLive(F&& f) {
    std::lock_guard lock(mutex_);
    if (stopped_ || state_ == ConnectionState::Refused) return false;
    f();
    return true;
  }

  // ---- caller side (any thread)

  // The first call marks the client stopped (true); later ones return false.
  [[nodiscard]] bool markStopped();
  // stop()'s end: state Stopped, waiters woken.
  void finishStopped();

  [[nodiscard]] ConnectionState state() const;
  [[nodiscard]] std::string stateReason() const;
  [[nodiscard]] std::optional<Hello> hello() const;
  [[nodiscard]] std::optional<Status> status() const;
  [[nodiscard]] std::optional<Received<LightFrame>> latestLightFrame() const;
  [[nodiscard]] std::optional<Received<EnvironmentFrame>> latestEnvironmentFrame() const;
  [[nodiscard]] ClientStats stats() const;
  [[nodiscard]] std::optional<Received<LightFrame>> waitForLightFrame(
      std::optional<std::uint64_t> afterSeq, std::chrono::milliseconds timeout) const;
  [[nodiscard]] bool waitForState(ConnectionState state, std::chrono::milliseconds timeout) const;

 private:
  void logState(ConnectionState next, const std::string& why);

  const StreamClientOptions& options_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  ConnectionState state_ = ConnectionState::Connecting;
  std::string reason_;
  std::optional<Hello> hello_;
  std::optional<Status> status_;
  std::optional<Received<LightFrame>> latestLight_;
  std::optional<Received<EnvironmentFrame>> latestEnvironment_;
  ReceptionStats reception_;
  ClientStats counters_;  // all but received, skipped and latency (from reception_)
  std::uint64_t connections_ = 0;
  std::map<std::uint64_t, std::promise<ControlResult>> pendingControls_;
  std::uint64_t nextRequestId_ = 1;
  std::string lastLoggedReason_;
  bool stopped_ = false;
};

}  // namespace vem::client
