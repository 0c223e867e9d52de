#include "client/vemview/adaptive_light_count.h"

#include <algorithm>
#include <cmath>

namespace vem::view {

AdaptiveLightCount::AdaptiveLightCount(double targetMs, std::size_t initial, std::size_t minCount,
                                       std::size_t maxCount)
    : targetMs_(targetMs),
      count_(std::clamp(initial, minCount, maxCount)),
      min_(minCount),
      max_(maxCount) {}

std::size_t AdaptiveLightCount::update(double measuredMs) {
  if (!(measuredMs > 0.0) || !std::isfinite(measuredMs)) {
    return count_;
  }
  double factor = 1.0;
  if (measuredMs > targetMs_ * (1.0 + kBand)) {
    factor = std::max(kMinStep, targetMs_ / measuredMs);
  } else if (measuredMs < targetMs_ * (1.0 - kBand)) {
    factor = std::min(kMaxGrowth, targetMs_ / measuredMs);
  }
  auto next = std::size_t(std::llround(double(count_) * factor));
  if (factor > 1.0) {
    next = std::max(next, count_ + 1);  // small counts still grow
  } else if (factor < 1.0 && count_ > 0) {
    next = std::min(next, count_ - 1);
  }
  count_ = std::clamp(next, min_, max_);
  return count_;
}

}  // namespace vem::view
