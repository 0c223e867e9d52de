#include "vemd/service_observer.h"

#include <chrono>
#include <utility>

#include "frames/frame_source.h"

namespace vem::vemd {

ServiceObserver::ServiceObserver(ServiceNotifier notifier) : notifier_(std::move(notifier)) {
  if (auto interval = notifier_.watchdogInterval()) {
    watchdogIntervalNs_ = std::chrono::duration_cast<std::chrono::nanoseconds>(*interval).count();
  }
}

void ServiceObserver::startupProgress() {
  if (!notifier_.enabled()) return;
  const std::int64_t now = monotonicNowNs();
  const std::int64_t intervalNs =
      std::chrono::duration_cast<std::chrono::nanoseconds>(kStartupProgressInterval).count();
  if (lastExtensionNs_ != 0 && now - lastExtensionNs_ < intervalNs) return;
  notifier_.extendTimeout(kStartupExtension);
  lastExtensionNs_ = now;
}

void ServiceObserver::firstFrameProcessed() {
  notifier_.ready();
  notifier_.status("running: the first frame is processed");
}

void ServiceObserver::alive() {
  if (watchdogIntervalNs_ <= 0) return;
  const std::int64_t now = monotonicNowNs();
  if (now - lastPingNs_ < watchdogIntervalNs_) return;
  notifier_.watchdog();
  lastPingNs_ = now;
}

void ServiceObserver::reported(const LoopReport&, const std::string& line) {
  notifier_.status(line);
}

void ServiceObserver::stopping() { notifier_.stopping(); }

}  // namespace vem::vemd
