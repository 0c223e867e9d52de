// CaptureThread: vemd's capture side, on a thread of its own: source.next() into the frame
// queue, and nothing else, so that processing and sinks can never hold it up (daemon_loop.h).
//
// - Frames go into `frames` with DropOldestQueue::push (drop-oldest), or pushOrWait when `lossless`
//   (a source without a pace of its own). Frames the daemon is done with come back through
//   `spares` and are handed to source.recycle(), on this thread.
// - Source errors: EndOfStream ends the thread; other causes are retried after a backoff that
//   doubles from retryInitial to retryMax, and are logged once per change of state: the first
//   failure of a cause, and the recovery ("frames again after N failed attempts").
// - After maxFrames frames (0: no limit) the thread ends. When it ends for any reason it closes
//   `frames`, so the consumer drains what is queued and then sees the end.
// - stop() (any thread) wakes the thread wherever it waits (in the source, in a backoff, for
//   room in the queue) and ends it; the destructor stops and joins.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>

#include "frames/captured_frame.h"
#include "frames/frame_source.h"
#include "util/backoff.h"
#include "util/drop_oldest_queue.h"
#include "vemd/pacer.h"

namespace vem::vemd {

struct CaptureOptions {
  std::uint64_t maxFrames = 0;
  bool lossless = false;
  std::chrono::milliseconds retryInitial{100};
  std::chrono::milliseconds retryMax{5000};
};

class CaptureThread {
 public:
  CaptureThread(FrameSource& source, util::DropOldestQueue<CapturedFrame>& frames,
                util::DropOldestQueue<CapturedFrame>& spares, const CaptureOptions& options);
  ~CaptureThread();
  CaptureThread(const CaptureThread&) = delete;
  CaptureThread& operator=(const CaptureThread&) = delete;

  void stop();
  void join();

  [[nodiscard]] bool endOfStream() const { return endOfStream_.load(); }
  [[nodiscard]] bool frameLimitReached() const { return limitReached_.load(); }
  [[nodiscard]] std::uint64_t sourceErrors() const { return sourceErrors_.load(); }
  // Why the source gives no frames now: the cause of the current run of failures, EndOfStream
  // once it ended; empty while frames flow (and before the first attempt). Any thread.
  [[nodiscard]] std::optional<SourceErrorCause> failure() const;

 private:
  void run();
  // Waits out one failed attempt (logged when the cause changed); false when stopped meanwhile.
  [[nodiscard]] bool backOff(const SourceError& error);
  void deliver(CapturedFrame frame);
  void recycleSpares();

  FrameSource& source_;
  util::DropOldestQueue<CapturedFrame>& frames_;
  util::DropOldestQueue<CapturedFrame>& spares_;
  CaptureOptions options_;
  Pacer backoffWait_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> endOfStream_{false};
  std::atomic<bool> limitReached_{false};
  std::atomic<std::uint64_t> sourceErrors_{0};
  std::atomic<std::uint64_t> delivered_{0};
  std::atomic<int> failure_{kNoFailure};  // a SourceErrorCause, or kNoFailure
  static constexpr int kNoFailure = -1;
  // Error state, on the capture thread only.
  bool failing_ = false;
  SourceErrorCause failingCause_ = SourceErrorCause::Timeout;
  std::uint64_t failedAttempts_ = 0;
  util::Backoff backoff_;
  std::thread thread_;  // last: starts once everything above is ready
};

}  // namespace vem::vemd
