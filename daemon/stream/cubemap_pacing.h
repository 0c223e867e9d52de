// When a cube map built by the stream sink's schedule (stream_sink.cpp: every 1/rate s of frames)
// goes to a subscriber that asked for `rateHz`: the worker builds at the fastest subscriber's pace
// and its messages come with its jitter, so one up to 10 % early is still sent. Gating at the full
// period dropped every one that came a little early, and a 5 Hz subscriber got about 3 a second
// (docs/BENCHMARKS.md, "MQTT fan-out"). Pure; monotonic nanoseconds.
#pragma once

#include <cstdint>
#include <limits>

namespace vem::stream {

class CubemapPacing {
 public:
  // Whether a cube map finished at `nowNs` goes out at `rateHz` (> 0); if so it counts as sent.
  [[nodiscard]] bool admit(std::int64_t nowNs, double rateHz) {
    const auto periodNs = std::int64_t(0.9e9 / rateHz);
    if (lastSentNs_ != kNever && nowNs - lastSentNs_ < periodNs) return false;
    lastSentNs_ = nowNs;
    return true;
  }

 private:
  static constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::min();
  std::int64_t lastSentNs_ = kNever;
};

}  // namespace vem::stream
