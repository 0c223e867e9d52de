// AdaptiveLightCount: holds a target frame time by changing how many lights are drawn, using the
// progressive property (core/light.h: the first k lights of a set are a good k-light set), so a
// change of count never changes which lights are drawn first.
//
// After each drawn frame of measured duration t (ms): when t > target (1 + kBand) the count drops
// by the factor max(kMinStep, target / t); when t < target (1 - kBand) it grows by
// min(kMaxGrowth, target / t); inside the band it stays (no oscillation). Always within
// [minCount, maxCount]. Pure: no clock, the caller passes the measurement.
#pragma once

#include <cstddef>

namespace vem::view {

inline constexpr double kBand = 0.1;
inline constexpr double kMinStep = 0.5;
inline constexpr double kMaxGrowth = 1.25;

class AdaptiveLightCount {
 public:
  AdaptiveLightCount(double targetMs, std::size_t initial, std::size_t minCount,
                     std::size_t maxCount);
  std::size_t update(double measuredMs);
  [[nodiscard]] std::size_t count() const { return count_; }

 private:
  double targetMs_;
  std::size_t count_;
  std::size_t min_;
  std::size_t max_;
};

}  // namespace vem::view
