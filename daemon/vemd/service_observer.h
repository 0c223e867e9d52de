// ServiceObserver: the daemon loop's events passed on to systemd (service_notifier.h): READY=1
// once the first frame went through the pipeline and the sinks, WATCHDOG=1 at half the watchdog
// timeout from the processing loop (so a hung pipeline or sink is noticed), STATUS= with each
// report line, STOPPING=1 when the loop begins to stop. Outside systemd it does nothing.
//
// Before the loop, start-up: startupProgress() is called between start-up steps and between the
// pieces of long ones (the polar remap's rows). At most once per kStartupProgressInterval it sends
// EXTEND_TIMEOUT_USEC of kStartupExtension, so a start-up that keeps making progress on a slower
// machine outlives the unit's TimeoutStartSec, while one that hangs (no progress for
// kStartupExtension) is still stopped by systemd.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "vemd/daemon_loop.h"
#include "vemd/service_notifier.h"

namespace vem::vemd {

inline constexpr std::chrono::seconds kStartupProgressInterval{1};
inline constexpr std::chrono::seconds kStartupExtension{10};

class ServiceObserver final : public LoopObserver {
 public:
  explicit ServiceObserver(ServiceNotifier notifier);

  void startupProgress();

  void firstFrameProcessed() override;
  void alive() override;
  void reported(const LoopReport& report, const std::string& line) override;
  void stopping() override;

  [[nodiscard]] const ServiceNotifier& notifier() const { return notifier_; }

 private:
  ServiceNotifier notifier_;
  std::int64_t watchdogIntervalNs_ = 0;  // 0: no watchdog
  std::int64_t lastPingNs_ = 0;
  std::int64_t lastExtensionNs_ = 0;  // 0: none sent yet
};

}  // namespace vem::vemd
