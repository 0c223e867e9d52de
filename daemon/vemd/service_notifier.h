// ServiceNotifier: tells systemd how vemd is doing when it runs as a Type=notify service
// (systemd/vemd.service), through libsystemd's sd_notify(3): readiness, watchdog pings, a one-line
// status, and that it is stopping. Outside systemd (no NOTIFY_SOCKET) every call does nothing.
//
// - The watchdog: systemd sets WATCHDOG_USEC (the unit's WatchdogSec) and WATCHDOG_PID;
//   sd_watchdog_enabled(3) reads them. Ping with watchdog() at least every watchdogInterval() (half
//   the timeout, as sd_watchdog_enabled(3) recommends); a missed timeout makes systemd kill and,
//   with Restart=on-failure, restart vemd. Ping from the loop that proves progress (the processing
//   loop), not from a timer thread that would keep pinging a hung pipeline.
// - Notifications are best effort: a failed send is ignored (systemd treats a silent service as
//   hung anyway). Each call is one datagram to the socket systemd names in NOTIFY_SOCKET.
// - status() text is one line: newlines become spaces, so it cannot add another assignment.
#pragma once

#include <chrono>
#include <optional>
#include <string_view>

namespace vem::vemd {

class ServiceNotifier {
 public:
  // Reads NOTIFY_SOCKET, WATCHDOG_USEC and WATCHDOG_PID once (the environment is left as it is).
  [[nodiscard]] static ServiceNotifier fromEnvironment();
  // A notifier that never sends (tests, or running in a terminal).
  ServiceNotifier() = default;

  // Whether systemd listens (NOTIFY_SOCKET was set).
  [[nodiscard]] bool enabled() const { return enabled_; }

  void ready() const;                        // READY=1: start-up finished, frames flow
  void watchdog() const;                     // WATCHDOG=1
  void status(std::string_view text) const;  // STATUS=text
  void stopping() const;                     // STOPPING=1: shutdown began
  // EXTEND_TIMEOUT_USEC=N: "still starting (or stopping): give me `by` more". Only matters once
  // the unit's TimeoutStartSec (TimeoutStopSec) has passed: systemd then waits as long as a new
  // message comes within `by` of the last (sd_notify(3)).
  void extendTimeout(std::chrono::microseconds by) const;

  // The watchdog timeout systemd enforces for this process, when it has one.
  [[nodiscard]] std::optional<std::chrono::microseconds> watchdogTimeout() const {
    return watchdogTimeout_;
  }
  // How often to call watchdog(): half the timeout; nullopt when no watchdog is set.
  [[nodiscard]] std::optional<std::chrono::microseconds> watchdogInterval() const;

 private:
  void send(std::string_view state) const;

  bool enabled_ = false;
  std::optional<std::chrono::microseconds> watchdogTimeout_;
};

}  // namespace vem::vemd
