// The daemon's two threads and what joins them:
//
//   capture thread:    source.next() --> DropOldestQueue (bounded, drops the oldest when full)
//   processing thread: DropOldestQueue --> pipeline.process() --> sinks --> statistics
//
// - The capture thread never waits for processing or sinks: when processing falls behind, the
//   queue drops the oldest waiting frame and counts it. The one exception is a source without a
//   pace of its own (a replay at --rate max): there "as fast as possible" means as fast as the
//   processing goes, so the capture thread waits for room and nothing is dropped.
// - Source errors: EndOfStream ends the run (the queue is drained first); every other cause is
//   logged once per change of state (and once when frames flow again) and retried with an
//   exponential backoff, so a lost camera is a state the daemon reports and recovers from.
// - Frames the pipeline cannot take (another size or format, codes out of range) are counted as
//   bad and skipped, logged once per distinct problem.
// - A sink that fails is logged once and dropped; the others keep going. All sinks are closed at
//   the end of the run (a recording gets its index), also after a stop request.
// - Stop: `stopRequested` (set from a signal handler, say) is polled at least every
//   kPollInterval; the current frame finishes, the capture thread is woken and joined, the sinks
//   are closed, and the final report is logged.
// - Control between frames: a LoopControl (optional, frames/loop_control.h) is called on the
//   processing thread before the first frame, after every frame and at least every kPollInterval,
//   never during a frame:
//   the place where requests from other threads (the stream server's control messages) change
//   the pipeline and where a status is published.
// - A paced source with a nominal rate that delivers below 90 % of it over 3 s is warned about
//   once, and once again when it is back at 97 % (rate_watch.h).
// - Reports: every reportEveryS seconds (0: never) and at the end, one log line each
//   (loop_statistics.h).
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "frames/frame_source.h"
#include "frames/loop_control.h"
#include "vemd/loop_statistics.h"
#include "vemd/pipeline.h"
#include "vemd/sink_set.h"

namespace vem::vemd {

inline constexpr std::chrono::milliseconds kPollInterval{50};

struct LoopOptions {
  std::size_t queueDepth = 4;
  std::uint64_t maxFrames = 0;  // stop after this many frames from the source; 0: no limit
  double reportEveryS = 5.0;    // 0: only the final report
  std::chrono::milliseconds retryInitial{100};
  std::chrono::milliseconds retryMax{5000};
};

// The loop's events for whoever supervises the process (the service manager's notifications).
// Called on the processing thread.
class LoopObserver {
 public:
  virtual ~LoopObserver() = default;
  virtual void firstFrameProcessed() {}
  // At least every kPollInterval while the loop runs: proof of life (a watchdog).
  virtual void alive() {}
  virtual void reported(const LoopReport& report, const std::string& line) {
    (void)report;
    (void)line;
  }
  virtual void stopping() {}
};

enum class StopReason { EndOfStream, FrameLimit, StopRequested };

[[nodiscard]] const char* stopReasonName(StopReason reason);

struct LoopResult {
  StopReason reason = StopReason::EndOfStream;
  LoopReport totals;
  std::uint64_t sinkFailures = 0;  // sinks dropped while running or failing to close
};

// Runs until the source ends, maxFrames frames came, or stopRequested becomes true. Starts the
// capture thread and joins it before returning; sinks are closed on return.
[[nodiscard]] LoopResult runDaemonLoop(FrameSource& source, Pipeline& pipeline, SinkSet& sinks,
                                       const LoopOptions& options,
                                       const std::atomic<bool>& stopRequested,
                                       LoopObserver* observer = nullptr,
                                       LoopControl* control = nullptr);

}  // namespace vem::vemd
