// Pacer: waits until a frame is due on CLOCK_MONOTONIC, and lets another thread cut the wait
// short (FrameSource::interrupt). Sources use it to keep a recording's or a scene's frame rate.
//
// Conventions: deadlines are CLOCK_MONOTONIC nanoseconds (std::chrono::steady_clock on Linux).
// An interrupt that arrives while nobody waits is kept for the next wait, so it is never lost;
// each interrupt ends exactly one wait. FrameSchedule (below) says when each frame is due.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>

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

// How far the capture time moved between two frames when that was not waited out.
struct TimestampJump {
  std::int64_t fromTsNs = 0;  // the previous frame's capture time
  std::int64_t toTsNs = 0;    // this frame's

  friend bool operator==(const TimestampJump&, const TimestampJump&) = default;
};

// When a frame goes out, and whether its capture time had to be overruled to get there.
struct FrameDue {
  std::int64_t dueNs = 0;             // CLOCK_MONOTONIC; nowNs or earlier: at once
  std::optional<TimestampJump> jump;  // following timestamps: this step was absurd (see below)
};

// When frames should go out: at their own timestamps' spacing (a recording), at a fixed period,
// or at once. Pure: the time now is an argument.
// - Each frame is due one step after the previous frame was: the fixed period, or the interval
//   between their capture times.
// - An interval that is negative or longer than kMaxRecordedIntervalNs (a capture time that jumps
//   back, or ahead by more than 10 s: a clock that was set, a damaged or hostile file) is never
//   waited out: the frame is due standInPeriodNs after the previous one instead (the recording's
//   nominal frame period), FrameDue::jump says so, and the frames after it keep their own
//   spacing. Differences are computed without overflow for any int64 capture times.
// - Re-anchors on the time now when the caller falls more than kMaxLagNs behind, so a stall is not
//   followed by a burst of frames at full speed.
class FrameSchedule {
 public:
  static constexpr std::int64_t kMaxLagNs = 1'000'000'000;
  static constexpr std::int64_t kMaxRecordedIntervalNs = 10'000'000'000;
  static constexpr std::int64_t kDefaultStandInPeriodNs = 33'333'333;  // 30 frames/s

  // periodNs > 0: a fixed rate; 0: follow the frames' timestamps; < 0: no pacing.
  // standInPeriodNs > 0: the step that replaces an absurd interval between timestamps.
  explicit FrameSchedule(std::int64_t periodNs,
                         std::int64_t standInPeriodNs = kDefaultStandInPeriodNs)
      : periodNs_(periodNs), standInPeriodNs_(standInPeriodNs) {}

  // The next frame, captured at `captureTsNs` (used when following timestamps), given the time
  // now.
  [[nodiscard]] FrameDue next(std::int64_t captureTsNs, std::int64_t nowNs);
  // next(captureTsNs, nowNs).dueNs
  [[nodiscard]] std::int64_t dueNs(std::int64_t captureTsNs, std::int64_t nowNs) {
    return next(captureTsNs, nowNs).dueNs;
  }

 private:
  // The step from the previous frame's due time to this one's.
  [[nodiscard]] std::int64_t stepNs(std::int64_t captureTsNs,
                                    std::optional<TimestampJump>& jump) const;

  std::int64_t periodNs_;
  std::int64_t standInPeriodNs_;
  bool started_ = false;
  std::int64_t previousDueNs_ = 0;
  std::int64_t previousTsNs_ = 0;
};

}  // namespace vem::vemd
