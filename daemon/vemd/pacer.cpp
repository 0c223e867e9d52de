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

FrameDue FrameSchedule::next(std::int64_t captureTsNs, std::int64_t nowNs) {
  if (periodNs_ < 0) return {nowNs, std::nullopt};
  FrameDue due{nowNs, std::nullopt};
  if (started_) {
    due.dueNs = previousDueNs_ + stepNs(captureTsNs, due.jump);
    if (nowNs - due.dueNs > kMaxLagNs) due.dueNs = nowNs;  // a stall: start again from now
  }
  started_ = true;
  previousDueNs_ = due.dueNs;
  previousTsNs_ = captureTsNs;
  return due;
}

std::int64_t FrameSchedule::stepNs(std::int64_t captureTsNs,
                                   std::optional<TimestampJump>& jump) const {
  if (periodNs_ > 0) return periodNs_;
  std::int64_t intervalNs = 0;
  const bool overflow = __builtin_sub_overflow(captureTsNs, previousTsNs_, &intervalNs);
  if (!overflow && intervalNs >= 0 && intervalNs <= kMaxRecordedIntervalNs) return intervalNs;
  jump = TimestampJump{previousTsNs_, captureTsNs};
  return standInPeriodNs_;
}

}  // namespace vem::vemd
