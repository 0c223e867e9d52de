#include "vemd/daemon_loop.h"

#include <chrono>
#include <optional>
#include <utility>

#include <spdlog/spdlog.h>

#include "util/printable.h"
#include "vemd/capture_thread.h"
#include "util/drop_oldest_queue.h"
#include "vemd/rate_watch.h"

namespace vem::vemd {

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::EndOfStream: return "the source ended";
    case StopReason::FrameLimit: return "the frame limit was reached";
    case StopReason::StopRequested: return "a stop was requested";
  }
  return "unknown";
}

namespace {

class NullObserver final : public LoopObserver {};

// The processing thread's work: queue -> pipeline -> sinks -> statistics, and the reports.
class ProcessingLoop {
 public:
  ProcessingLoop(Pipeline& pipeline, SinkSet& sinks, const LoopOptions& options,
                 const SourceDescription& source, LoopObserver& observer, LoopControl* control)
      : pipeline_(pipeline),
        sinks_(sinks),
        options_(options),
        liveClock_(source.liveClock),
        observer_(observer),
        control_(control),
        stats_(monotonicNowNs()),
        nextReportNs_(monotonicNowNs() + reportPeriodNs()),
        sourceSpec_(util::printable(source.spec)) {
    if (source.paced && source.nominalRateHz > 0.0) rateWatch_.emplace(source.nominalRateHz);
  }

  StopReason run(util::DropOldestQueue<CapturedFrame>& frames, util::DropOldestQueue<CapturedFrame>& spares,
                 const CaptureThread& capture, const std::atomic<bool>& stopRequested) {
    applyControl(frames.counters(), capture);
    for (;;) {
      if (stopRequested.load()) return StopReason::StopRequested;
      std::optional<CapturedFrame> captured = frames.popFor(kPollInterval);
      if (captured) {
        handle(*captured);
        (void)spares.push(std::move(*captured));
      } else if (frames.finished()) {
        return capture.frameLimitReached() ? StopReason::FrameLimit : StopReason::EndOfStream;
      }
      observer_.alive();
      applyControl(frames.counters(), capture);
      watchRate(frames.counters(), capture);
      reportIfDue(frames.counters(), capture.sourceErrors());
    }
  }

  // The data flow of one frame.
  void handle(const CapturedFrame& captured) {
    if (auto problem = pipeline_.frameProblem(captured.frame)) return refuse(captured, *problem);
    acceptAgain();
    const ProcessedFrame& processed = pipeline_.process(captured);
    const double sinksMicros = feedSinks(processed);
    lastProcessedNs_ = monotonicNowNs();
    stats_.frameProcessed(processed, sinksMicros, lastProcessedNs_, liveClock_);
    if (stats_.processed() == 1) observer_.firstFrameProcessed();
  }

  LoopResult finish(StopReason reason, const util::QueueCounters& queue, std::uint64_t sourceErrors) {
    std::vector<std::string> notes = sinks_.notes();  // before the sinks are closed
    for (const DroppedSink& failed : sinks_.closeAll()) {
      spdlog::error("sink {}: {}", failed.name, util::printable(failed.message, 1024));
      ++sinkFailures_;
    }
    LoopResult result{reason, stats_.totals(monotonicNowNs(), queue, sourceErrors), sinkFailures_};
    result.totals.notes = std::move(notes);
    spdlog::info("{}", formatReport(result.totals, "final"));
    return result;
  }

 private:
  [[nodiscard]] std::int64_t reportPeriodNs() const {
    return std::int64_t(options_.reportEveryS * 1e9);
  }

  double feedSinks(const ProcessedFrame& processed) {
    const auto start = std::chrono::steady_clock::now();
    for (const DroppedSink& failed : sinks_.consume(processed)) {
      spdlog::error("sink {}: {}; the sink is dropped, the others go on", failed.name,
                    util::printable(failed.message, 1024));
      ++sinkFailures_;
    }
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
        .count();
  }

  void applyControl(const util::QueueCounters& queue, const CaptureThread& capture) {
    if (control_ == nullptr) return;
    control_->betweenFrames(
        pipeline_, {stats_.processed(), queue.dropped, refusedTotal_, capture.sourceErrors(),
                    lastProcessedNs_, capture.failure()});
  }

  void refuse(const CapturedFrame& captured, const std::string& problem) {
    stats_.frameRefused();
    ++refusedTotal_;
    ++refusedInARow_;
    if (refusedInARow_ == 1) {
      spdlog::warn(
          "frame {} refused: {} (refused frames are counted, not logged again until a "
          "frame is accepted)",
          captured.seq, problem);
    }
  }

  void acceptAgain() {
    if (refusedInARow_ == 0) return;
    spdlog::info("frames accepted again after {} refused", refusedInARow_);
    refusedInARow_ = 0;
  }

  // A paced source below its nominal rate (rate_watch.h), logged once per change of state; a
  // source that fails is reported as such, and its window starts again when frames flow.
  void watchRate(const util::QueueCounters& queue, const CaptureThread& capture) {
    if (!rateWatch_) return;
    if (capture.failure()) return rateWatch_->restart();
    const auto change = rateWatch_->observe(monotonicNowNs(), queue.pushed);
    if (!change) return;
    const RateWatchOptions& o = rateWatch_->options();
    if (change->below) {
      spdlog::warn(
          "source {} delivers {:.1f} frames/s over the last {:.0f} s, below {:.0f} % of its "
          "nominal {:.1f} frames/s: it cannot keep its rate (these frames are never made, so "
          "they are not counted as dropped; logged again when it is back above {:.0f} %)",
          sourceSpec_, change->measuredHz, o.windowS, o.belowFraction * 100.0, change->nominalHz,
          o.recoveredFraction * 100.0);
    } else {
      spdlog::info("source {} is back at its rate: {:.1f} frames/s of a nominal {:.1f}",
                   sourceSpec_, change->measuredHz, change->nominalHz);
    }
  }

  void reportIfDue(const util::QueueCounters& queue, std::uint64_t sourceErrors) {
    if (options_.reportEveryS <= 0.0) return;
    const std::int64_t now = monotonicNowNs();
    if (now < nextReportNs_) return;
    LoopReport report = stats_.takeWindow(now, queue, sourceErrors);
    report.notes = sinks_.notes();
    const std::string line = formatReport(report, "stats");
    spdlog::info("{}", line);
    observer_.reported(report, line);
    nextReportNs_ = now + reportPeriodNs();
  }

  Pipeline& pipeline_;
  SinkSet& sinks_;
  const LoopOptions& options_;
  bool liveClock_;
  LoopObserver& observer_;
  LoopControl* control_;  // may be null
  LoopStatistics stats_;
  std::int64_t nextReportNs_;
  std::string sourceSpec_;
  std::optional<RateWatch> rateWatch_;  // paced sources with a nominal rate
  std::uint64_t refusedInARow_ = 0;
  std::uint64_t sinkFailures_ = 0;
  std::uint64_t refusedTotal_ = 0;
  std::int64_t lastProcessedNs_ = 0;
};

}  // namespace

LoopResult runDaemonLoop(FrameSource& source, Pipeline& pipeline, SinkSet& sinks,
                         const LoopOptions& options, const std::atomic<bool>& stopRequested,
                         LoopObserver* observer, LoopControl* control) {
  NullObserver none;
  LoopObserver& watcher = observer != nullptr ? *observer : none;
  const SourceDescription description = source.describe();
  util::DropOldestQueue<CapturedFrame> frames(options.queueDepth);
  util::DropOldestQueue<CapturedFrame> spares(options.queueDepth + 2);
  ProcessingLoop processing(pipeline, sinks, options, description, watcher, control);
  CaptureThread capture(
      source, frames, spares,
      {options.maxFrames, !description.paced, options.retryInitial, options.retryMax});
  const StopReason reason = processing.run(frames, spares, capture, stopRequested);
  spdlog::info("stopping: {}", stopReasonName(reason));
  watcher.stopping();
  capture.stop();
  capture.join();
  return processing.finish(reason, frames.counters(), capture.sourceErrors());
}

}  // namespace vem::vemd
