// LightFrameLog: what one StreamClient received, frame by frame, for the end-to-end tests: each
// light frame's seq, its receipt time and a digest of its lights (FNV-1a 64 over every light's id
// and the bits of its dir and rgb, in order), so that two clients' frames compare exactly without
// keeping the lights. Fed from StreamClient's onLightFrame callback (the client's I/O thread) and
// read from the test's thread: thread-safe.
//
// Times: receivedAt on the steady clock. Rates in frames per second.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "client/stream_client.h"

namespace vem::e2e {

struct LoggedFrame {
  std::uint64_t seq = 0;
  std::size_t lightCount = 0;
  std::uint64_t lightsDigest = 0;
  std::chrono::steady_clock::time_point receivedAt;
};

[[nodiscard]] std::uint64_t lightsDigest(const LightSet& lights);

class LightFrameLog {
 public:
  void record(const client::Received<client::LightFrame>& received);
  [[nodiscard]] std::vector<LoggedFrame> frames() const;
  // The frames with firstSeq <= seq <= lastSeq, in the order received.
  [[nodiscard]] std::vector<LoggedFrame> framesBetween(std::uint64_t firstSeq,
                                                       std::uint64_t lastSeq) const;
  [[nodiscard]] std::size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::vector<LoggedFrame> frames_;
};

// Gaps in the seqs of `frames` (seq 5 after 2: 2 missing), over consecutive frames in the order
// received; a seq at or below the previous one counts as one gap (it should never happen).
[[nodiscard]] std::uint64_t missingSeqs(const std::vector<LoggedFrame>& frames);
// Frames received per second between the first and the last frame's receipt (0 with fewer than 2):
// (count - 1) / elapsed.
[[nodiscard]] double receivedRateHz(const std::vector<LoggedFrame>& frames);
// Frames received per second counted by seq: (last seq - first seq) / elapsed, the daemon's
// processed rate as this client saw it, gaps included.
[[nodiscard]] double seqRateHz(const std::vector<LoggedFrame>& frames);

}  // namespace vem::e2e
