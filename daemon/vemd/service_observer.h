// ServiceObserver: the daemon loop's events passed on to systemd (service_notifier.h): READY=1
// once the first frame went through the pipeline and the sinks, WATCHDOG=1 at half the watchdog
// timeout from the processing loop (so a hung pipeline or sink is noticed), STATUS= with each
// report line, STOPPING=1 when the loop begins to stop. Outside systemd it does nothing.
#pragma once

#include <cstdint>
#include <string>

#include "vemd/daemon_loop.h"
#include "vemd/service_notifier.h"

namespace vem::vemd {

class ServiceObserver final : public LoopObserver {
 public:
  explicit ServiceObserver(ServiceNotifier notifier);

  void firstFrameProcessed() override;
  void alive() override;
  void reported(const LoopReport& report, const std::string& line) override;
  void stopping() override;

  [[nodiscard]] const ServiceNotifier& notifier() const { return notifier_; }

 private:
  ServiceNotifier notifier_;
  std::int64_t watchdogIntervalNs_ = 0;  // 0: no watchdog
  std::int64_t lastPingNs_ = 0;
};

}  // namespace vem::vemd
