#include "vemd/rate_watch.h"

namespace vem::vemd {

RateWatch::RateWatch(double nominalHz, RateWatchOptions options)
    : nominalHz_(nominalHz), options_(options) {}

std::optional<RateChange> RateWatch::observe(std::int64_t nowNs, std::uint64_t framesTotal) {
  if (samples_.empty() && framesTotal == 0) return std::nullopt;  // before the first frame
  samples_.push_back({nowNs, framesTotal});
  const auto windowNs = std::int64_t(options_.windowS * 1e9);
  // Keep one sample at or before the window's start, none older.
  while (samples_.size() > 1 && samples_[1].ns <= nowNs - windowNs) samples_.pop_front();
  const Sample& first = samples_.front();
  const std::int64_t spanNs = nowNs - first.ns;
  if (spanNs < windowNs) return std::nullopt;
  const double measuredHz = double(framesTotal - first.frames) / (double(spanNs) * 1e-9);
  const double fraction = measuredHz / nominalHz_;
  if (!below_ && fraction < options_.belowFraction) {
    below_ = true;
    return RateChange{true, measuredHz, nominalHz_};
  }
  if (below_ && fraction >= options_.recoveredFraction) {
    below_ = false;
    return RateChange{false, measuredHz, nominalHz_};
  }
  return std::nullopt;
}

void RateWatch::restart() { samples_.clear(); }

}  // namespace vem::vemd
