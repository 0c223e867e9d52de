#include "client/reception_stats.h"

#include <algorithm>
#include <cmath>

namespace vem::client {

ReceptionStats::ReceptionStats(std::size_t window) : window_(std::max<std::size_t>(window, 1)) {
  latencyMs_.reserve(window_);
}

void ReceptionStats::onLightFrame(std::uint64_t seq, std::int64_t publishUnixNs,
                                  std::int64_t receivedUnixNs) {
  ++received_;
  if (lastSeq_ && seq > *lastSeq_) skipped_ += seq - *lastSeq_ - 1;
  lastSeq_ = seq;
  const double latencyMs = double(receivedUnixNs - publishUnixNs) * 1e-6;
  if (latencyMs_.size() < window_) {
    latencyMs_.push_back(latencyMs);
  } else {
    latencyMs_[nextSlot_] = latencyMs;
  }
  nextSlot_ = (nextSlot_ + 1) % window_;
}

LatencySummary ReceptionStats::latency() const {
  LatencySummary summary;
  summary.samples = latencyMs_.size();
  if (latencyMs_.empty()) return summary;
  std::vector<double> sorted = latencyMs_;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  summary.medianMs = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  // Nearest rank: the smallest sample with at least 99 % of the samples at or below it.
  const std::size_t rank = std::size_t(std::ceil(0.99 * double(n)));
  summary.p99Ms = sorted[std::max<std::size_t>(rank, 1) - 1];
  return summary;
}

}  // namespace vem::client
