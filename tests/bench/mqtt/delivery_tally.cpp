#include "bench/mqtt/delivery_tally.h"

#include <algorithm>

#include "bench/measurements.h"
#include "proto/vem_stream.pb.h"

namespace vem::bench {

void DeliveryTally::record(std::string_view payload, std::int64_t receivedUnixNs, bool counting) {
  // One message object per thread, reused: parsing keeps its buffers.
  thread_local stream::ServerMessage message;
  if (!message.ParseFromArray(payload.data(), int(payload.size())) || !message.has_lights()) {
    return;
  }
  const stream::LightFrame& frame = message.lights();
  const std::uint64_t seq = frame.seq();
  if (counting) {
    ++frames_;
    bytes_ += payload.size();
    latenciesMs_.push_back(double(receivedUnixNs - frame.publish_unix_ns()) * 1e-6);
    if (lastSeq_ && seq <= *lastSeq_) ++repeated_;
    if (lastSeq_ && seq > *lastSeq_ + 1) seqGaps_ += seq - *lastSeq_ - 1;
  }
  if (!lastSeq_ || seq > *lastSeq_) lastSeq_ = seq;
}

DeliverySummary summarize(const std::vector<const DeliveryTally*>& tallies, double windowS) {
  DeliverySummary s;
  s.subscribers = tallies.size();
  if (tallies.empty() || windowS <= 0.0) return s;
  std::vector<double> latencies;
  std::uint64_t bytes = 0;
  std::uint64_t fewest = tallies.front()->frames();
  for (const DeliveryTally* t : tallies) {
    s.frames += t->frames();
    s.seqGaps += t->seqGaps();
    s.repeated += t->repeated();
    bytes += t->bytes();
    fewest = std::min(fewest, t->frames());
    latencies.insert(latencies.end(), t->latenciesMs().begin(), t->latenciesMs().end());
  }
  s.framesPerSubscriberS = double(s.frames) / double(tallies.size()) / windowS;
  s.minFramesPerSubscriberS = double(fewest) / windowS;
  s.bytesPerS = double(bytes) / windowS;
  s.latencyMedianMs = quantile(latencies, 0.5);
  s.latencyP99Ms = quantile(latencies, 0.99);
  s.latencyMaxMs = latencies.empty() ? 0.0 : std::ranges::max(latencies);
  return s;
}

}  // namespace vem::bench
