#include "vemd/source_rate.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace vem::vemd {

std::optional<SourceRate> parseSourceRate(std::string_view text) {
  if (text == "recorded") return SourceRate{SourceRate::Mode::Recorded, 0.0};
  if (text == "max") return SourceRate{SourceRate::Mode::Max, 0.0};
  double hz = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), hz);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(hz) || hz <= 0.0 ||
      hz > kMaxRateHz) {
    return std::nullopt;
  }
  return SourceRate{SourceRate::Mode::Fixed, hz};
}

std::string formatSourceRate(const SourceRate& rate) {
  switch (rate.mode) {
    case SourceRate::Mode::Recorded: return "recorded";
    case SourceRate::Mode::Max: return "max";
    case SourceRate::Mode::Fixed: break;
  }
  return fmt::format("{}", rate.hz);
}

long long schedulePeriodNs(const SourceRate& rate) {
  switch (rate.mode) {
    case SourceRate::Mode::Recorded: return 0;
    case SourceRate::Mode::Max: return -1;
    case SourceRate::Mode::Fixed: break;
  }
  return std::max(1LL, std::llround(1e9 / rate.hz));
}

}  // namespace vem::vemd
