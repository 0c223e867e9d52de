#include "stream/client_lag.h"

#include <algorithm>

namespace vem::stream {

std::optional<std::uint64_t> ClientLag::probeSent(std::int64_t nowNs) {
  if (probes_.size() >= options_.maxProbes) return std::nullopt;
  const std::uint64_t id = nextId_++;
  probes_.push_back({id, nowNs});
  return id;
}

void ClientLag::pongReceived(std::uint64_t id, std::int64_t nowNs) {
  if (probes_.empty() || id < probes_.front().id || id > probes_.back().id) return;
  const auto confirmed = std::ranges::find(probes_, id, &Probe::id);
  if (confirmed == probes_.end()) return;
  const std::int64_t roundTripNs = std::max<std::int64_t>(0, nowNs - confirmed->sentNs);
  lastRoundTripNs_ = roundTripNs;
  minRoundTripNs_ = std::min(minRoundTripNs_.value_or(roundTripNs), roundTripNs);
  maxRoundTripNs_ = std::max(maxRoundTripNs_, roundTripNs);
  probes_.erase(probes_.begin(), confirmed + 1);
}

bool ClientLag::mayWrite(std::int64_t nowNs) const {
  if (probes_.empty()) return true;
  if (probes_.size() >= options_.maxProbes) return false;
  return lagNs(nowNs) < minRoundTripNs_.value_or(0) + options_.slackNs;
}

std::int64_t ClientLag::lagNs(std::int64_t nowNs) const {
  return probes_.empty() ? 0 : std::max<std::int64_t>(0, nowNs - probes_.front().sentNs);
}

}  // namespace vem::stream
