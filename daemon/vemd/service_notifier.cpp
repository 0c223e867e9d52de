#include "vemd/service_notifier.h"

#include <systemd/sd-daemon.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace vem::vemd {

ServiceNotifier ServiceNotifier::fromEnvironment() {
  ServiceNotifier notifier;
  const char* socket = std::getenv("NOTIFY_SOCKET");
  notifier.enabled_ = socket != nullptr && *socket != '\0';
  std::uint64_t timeoutUs = 0;
  // > 0 only when WATCHDOG_USEC is set and WATCHDOG_PID, if set, is this process.
  if (::sd_watchdog_enabled(0, &timeoutUs) > 0 && timeoutUs > 0) {
    notifier.watchdogTimeout_ = std::chrono::microseconds(timeoutUs);
  }
  return notifier;
}

std::optional<std::chrono::microseconds> ServiceNotifier::watchdogInterval() const {
  if (!watchdogTimeout_) return std::nullopt;
  return *watchdogTimeout_ / 2;
}

void ServiceNotifier::ready() const { send("READY=1"); }

void ServiceNotifier::watchdog() const { send("WATCHDOG=1"); }

void ServiceNotifier::status(std::string_view text) const {
  std::string state = "STATUS=";
  state += text;
  std::ranges::replace(state, '\n', ' ');
  send(state);
}

void ServiceNotifier::stopping() const { send("STOPPING=1"); }

void ServiceNotifier::extendTimeout(std::chrono::microseconds by) const {
  send("EXTEND_TIMEOUT_USEC=" + std::to_string(std::max<std::int64_t>(0, by.count())));
}

void ServiceNotifier::send(std::string_view state) const {
  if (!enabled_) return;
  const std::string text(state);
  (void)::sd_notify(0, text.c_str());
}

}  // namespace vem::vemd
