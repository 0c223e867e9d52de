// ReceptionStats: what a client counts about the light frames it receives.
// - received: light frames accepted;
// - skipped: frames the client never saw, from the gaps between the sequence numbers of successive
//   received frames (seq 5 after seq 2 skipped 3 and 4). A seq at or below the last one (a
//   restarted daemon, a replay that looped) starts counting again from it and skips nothing;
// - latency: receipt time minus the frame's publish_unix_ns, both CLOCK_REALTIME (meaningful across
//   hosts only as far as their clocks agree), in ms, median and 99th percentile over the last
//   `window` frames.
// Pure value type: the caller passes the times; not thread-safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace vem::client {

struct LatencySummary {
  std::size_t samples = 0;  // in the window
  double medianMs = 0.0;    // 0 when there are no samples
  double p99Ms = 0.0;
};

class ReceptionStats {
 public:
  explicit ReceptionStats(std::size_t window = 1000);

  void onLightFrame(std::uint64_t seq, std::int64_t publishUnixNs, std::int64_t receivedUnixNs);

  [[nodiscard]] std::uint64_t received() const { return received_; }
  [[nodiscard]] std::uint64_t skipped() const { return skipped_; }
  [[nodiscard]] LatencySummary latency() const;

 private:
  std::size_t window_;
  std::vector<double> latencyMs_;  // a ring of the last window_ samples
  std::size_t nextSlot_ = 0;
  std::optional<std::uint64_t> lastSeq_;
  std::uint64_t received_ = 0;
  std::uint64_t skipped_ = 0;
};

}  // namespace vem::client
