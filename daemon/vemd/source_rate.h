// SourceRate: the pace a source delivers frames at, as `--rate` and `source.rate` spell it:
// "recorded" (a recording's own timestamps; a synthetic scene's nominal rate), "max" (as fast as
// the daemon takes them) or a number of frames per second.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace vem::vemd {

inline constexpr double kMaxRateHz = 10000.0;

struct SourceRate {
  enum class Mode { Recorded, Max, Fixed };
  Mode mode = Mode::Recorded;
  double hz = 0.0;  // for Fixed: > 0 and at most kMaxRateHz

  friend bool operator==(const SourceRate&, const SourceRate&) = default;
};

// "recorded", "max", or a positive number up to kMaxRateHz ("30", "29.97"); nullopt otherwise.
[[nodiscard]] std::optional<SourceRate> parseSourceRate(std::string_view text);
// "recorded", "max" or the number ("30").
[[nodiscard]] std::string formatSourceRate(const SourceRate& rate);

// Nanoseconds between frames for a FrameSchedule: the fixed period, 0 (follow the timestamps) for
// Recorded, -1 (no pacing) for Max.
[[nodiscard]] long long schedulePeriodNs(const SourceRate& rate);

}  // namespace vem::vemd
