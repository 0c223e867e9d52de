// RateWatch: tells when a paced source delivers fewer frames than its nominal rate, and when it is
// back at it, once per change of state (a synthetic scene rendering at 3.9 frames/s against a
// nominal 30 showed "0 dropped": the frames were never made, so nothing counted them).
//
// The measured rate is the frames delivered over the last `windowS` seconds (the running total
// sampled at each call, CLOCK_MONOTONIC nanoseconds). It is judged only once a whole window of
// samples is there, counted from the first delivered frame (start-up is not a slow source).
// Below `belowFraction` of the nominal rate the state turns to "below"; it turns back only at
// `recoveredFraction` or more (hysteresis: a rate hovering at the threshold does not flap).
// Pure: no clock, no logging; the caller passes the times in and logs the changes.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>

namespace vem::vemd {

struct RateWatchOptions {
  double windowS = 3.0;
  double belowFraction = 0.90;      // below this fraction of nominal: "below"
  double recoveredFraction = 0.97;  // at or above this fraction again: "back"
};

struct RateChange {
  bool below = false;  // true: fell below; false: back at the rate
  double measuredHz = 0.0;
  double nominalHz = 0.0;
};

class RateWatch {
 public:
  // `nominalHz` > 0.
  explicit RateWatch(double nominalHz, RateWatchOptions options = {});

  // The running total of frames the source delivered, at `nowNs` (non-decreasing); a change of
  // state, or nullopt.
  [[nodiscard]] std::optional<RateChange> observe(std::int64_t nowNs, std::uint64_t framesTotal);
  // Forgets the window (the source failed and is retried: that is reported on its own); the state
  // stays, so a source that comes back slow is not reported twice.
  void restart();

  [[nodiscard]] bool below() const { return below_; }
  [[nodiscard]] const RateWatchOptions& options() const { return options_; }

 private:
  struct Sample {
    std::int64_t ns;
    std::uint64_t frames;
  };
  double nominalHz_;
  RateWatchOptions options_;
  std::deque<Sample> samples_;  // oldest first; the first one at or before the window's start
  bool below_ = false;
};

}  // namespace vem::vemd
