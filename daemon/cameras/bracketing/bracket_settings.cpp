#include "cameras/bracketing/bracket_settings.h"

#include <cmath>

#include <fmt/format.h>

#include "util/contract.h"

namespace vem::cameras {

std::optional<std::string> bracketSettingsProblem(const BracketSettings& s) {
  if (s.count < kMinBracketCount || s.count > kMaxBracketCount) {
    return fmt::format("bracketing count is {}: expected {} to {} exposures per group", s.count,
                       kMinBracketCount, kMaxBracketCount);
  }
  if (!(s.stopsApart >= kMinStopsApart && s.stopsApart <= kMaxStopsApart)) {
    return fmt::format("bracketing stops is {}: expected {} to {} stops between exposures",
                       s.stopsApart, kMinStopsApart, kMaxStopsApart);
  }
  if (!(s.baseExposureUs > 0.0 && std::isfinite(s.baseExposureUs))) {
    return fmt::format("bracketing base_exposure_us is {}: expected a shortest exposure above 0 us",
                       s.baseExposureUs);
  }
  const double longestUs = s.baseExposureUs * std::exp2(s.stopsApart * (s.count - 1));
  if (!(longestUs <= kMaxBracketExposureUs)) {
    return fmt::format(
        "bracketing base_exposure_us {} with {} exposures {} stops apart makes the longest "
        "{} us: expected at most {} us",
        s.baseExposureUs, s.count, s.stopsApart, longestUs, kMaxBracketExposureUs);
  }
  if (!(s.gain > 0.0 && s.gain <= kMaxBracketGain)) {
    return fmt::format("bracketing gain is {}: expected a linear gain above 0 and at most {}",
                       s.gain, kMaxBracketGain);
  }
  const double ratio = std::exp2(s.stopsApart);
  const double widest = (ratio - 1.0) / (ratio + 1.0);
  if (!(s.matchTolerance > 0.0 && s.matchTolerance < widest)) {
    return fmt::format(
        "bracketing match_tolerance is {}: expected above 0 and below {:.3g} (exposures {} stops "
        "apart must not both match one frame)",
        s.matchTolerance, widest, s.stopsApart);
  }
  return std::nullopt;
}

std::vector<double> bracketExposuresUs(const BracketSettings& settings) {
  VEM_EXPECTS(!bracketSettingsProblem(settings));
  std::vector<double> exposures;
  for (int k = 0; k < settings.count; ++k) {
    exposures.push_back(settings.baseExposureUs * std::exp2(settings.stopsApart * k));
  }
  return exposures;
}

}  // namespace vem::cameras
