#include "vemd/pacer.h"

#include <chrono>

namespace vem::vemd {

bool Pacer::sleepUntil(std::int64_t deadlineNs) {
  const std::chrono::steady_clock::time_point deadline{std::chrono::nanoseconds(deadlineNs)};
  std::unique_lock lock(mutex_);
  wake_.wait_until(lock, deadline, [&] { return interrupted_; });
  const bool interrupted = interrupted_;
  interrupted_ = false;
  return !interrupted;
}

void Pacer::interrupt() {
  {
    std::lock_guard lock(mutex_);
    interrupted_ = true;
  }
  wake_.notify_all();
}

std::int64_t FrameSchedule::dueNs(std::int64_t captureTsNs, std::int64_t nowNs) {
  if (periodNs_ < 0) return nowNs;
  if (!anchored_) {
    anchored_ = true;
    originMonoNs_ = nowNs;
    originTsNs_ = captureTsNs;
    framesSinceOrigin_ = 0;
  }
  const std::int64_t due = periodNs_ > 0 ? originMonoNs_ + framesSinceOrigin_ * periodNs_
                                         : originMonoNs_ + (captureTsNs - originTsNs_);
  if (nowNs - due > kMaxLagNs) {
    anchored_ = false;
    return dueNs(captureTsNs, nowNs);
  }
  ++framesSinceOrigin_;
  return due;
}

}  // namespace vem::vemd
