// Pacer: waits until a frame is due on CLOCK_MONOTONIC, and lets another thread cut the wait
// short (FrameSource::interrupt). Sources use it to keep a recording's or a scene's frame rate.
//
// Conventions: deadlines are CLOCK_MONOTONIC nanoseconds (std::chrono::steady_clock on Linux).
// An interrupt that arrives while nobody waits is kept for the next wait, so it is never lost;
// each interrupt ends exactly one wait.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace vem::vemd {

class Pacer {
 public:
  // Returns true at the deadline (at once when it has passed), false when interrupted first.
  [[nodiscard]] bool sleepUntil(std::int64_t deadlineNs);
  void interrupt();

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool interrupted_ = false;
};

// When frames should go out: at their own timestamps' spacing (a recording), at a fixed period,
// or at once. Re-anchors when the caller falls more than kMaxLagNs behind, so a stall is not
// followed by a burst of frames at full speed.
class FrameSchedule {
 public:
  static constexpr std::int64_t kMaxLagNs = 1'000'000'000;

  // periodNs > 0: a fixed rate; 0: follow the frames' timestamps; < 0: no pacing.
  explicit FrameSchedule(std::int64_t periodNs) : periodNs_(periodNs) {}

  // The CLOCK_MONOTONIC instant the next frame (captured at `captureTsNs`, used when following
  // timestamps) is due, given the time now: nowNs or earlier when it is due at once.
  [[nodiscard]] std::int64_t dueNs(std::int64_t captureTsNs, std::int64_t nowNs);

 private:
  std::int64_t periodNs_;
  bool anchored_ = false;
  std::int64_t originMonoNs_ = 0;
  std::int64_t originTsNs_ = 0;
  std::int64_t framesSinceOrigin_ = 0;
};

}  // namespace vem::vemd
