// DeliveryTally: what one subscriber received of one camera's light frames, over a measuring
// window: the frames, the seq gaps (frames it never saw: dropped by the broker, by vemd's MQTT
// queue or by vemd's capture queue, or skipped by vemd's newest-only WebSocket queue), frames that
// came again or out of order, the payload bytes, and each frame's latency from its
// publish_unix_ns (vemd's processing done) to its receipt here, both CLOCK_REALTIME, in ms.
//
// One tally belongs to one subscriber and is written by one thread; a summary adds many up once
// the subscribers have stopped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace vem::bench {

class DeliveryTally {
 public:
  // One received payload (a serialized ServerMessage): light frames are counted while `counting`,
  // other messages and payloads that do not decode are ignored. `receivedUnixNs` is when it was
  // read (CLOCK_REALTIME). Seq gaps are counted between two frames of which the second arrived
  // while counting.
  void record(std::string_view payload, std::int64_t receivedUnixNs, bool counting);

  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t seqGaps() const { return seqGaps_; }
  [[nodiscard]] std::uint64_t repeated() const { return repeated_; }
  [[nodiscard]] std::uint64_t bytes() const { return bytes_; }
  [[nodiscard]] const std::vector<double>& latenciesMs() const { return latenciesMs_; }

 private:
  std::uint64_t frames_ = 0;
  std::uint64_t seqGaps_ = 0;
  std::uint64_t repeated_ = 0;  // seq not above the last one (a retained frame again, reordering)
  std::uint64_t bytes_ = 0;
  std::optional<std::uint64_t> lastSeq_;
  std::vector<double> latenciesMs_;
};

// Many subscribers' tallies over a window of `windowS` seconds.
struct DeliverySummary {
  std::size_t subscribers = 0;
  std::uint64_t frames = 0;              // all subscribers together
  double framesPerSubscriberS = 0.0;     // mean over the subscribers, per second
  double minFramesPerSubscriberS = 0.0;  // the slowest subscriber's, per second
  std::uint64_t seqGaps = 0;             // all subscribers together
  std::uint64_t repeated = 0;
  double bytesPerS = 0.0;        // payload bytes all subscribers received per second
  double latencyMedianMs = 0.0;  // over every frame every subscriber received
  double latencyP99Ms = 0.0;
  double latencyMaxMs = 0.0;
};

[[nodiscard]] DeliverySummary summarize(const std::vector<const DeliveryTally*>& tallies,
                                        double windowS);

}  // namespace vem::bench
