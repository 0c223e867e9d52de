// LoopStatistics: what vemd measures while it runs, and the report lines it prints every few
// seconds and at exit: frames in (delivered by the source), processed, dropped by the queue, bad
// (refused before processing), source errors; the processing rate; per-stage time; latency.
//
// Units and clocks: stage times in microseconds per frame (mean and max over the window);
// latencies in milliseconds on CLOCK_MONOTONIC, both up to the moment every sink is done with the
// frame: "from arrival" starts at the frame's arrivalNs (vemd received it: vemd's own time),
// "from capture" at its captureTsNs (the camera took it: adds the camera's and the driver's
// delay), only for sources whose timestamps are CLOCK_MONOTONIC (live sources). Pure: the caller
// passes the times in.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "frames/processed_frame.h"
#include "util/drop_oldest_queue.h"

namespace vem::vemd {

// Count, mean and maximum of a series.
struct RunningStat {
  std::uint64_t count = 0;
  double sum = 0.0;
  double max = 0.0;

  void add(double value);
  [[nodiscard]] double mean() const { return count > 0 ? sum / double(count) : 0.0; }
};

struct StageStat {
  std::string stage;
  RunningStat micros;
};

// One report: a window since the last report, or the whole run.
struct LoopReport {
  double elapsedS = 0.0;
  std::uint64_t framesIn = 0;
  std::uint64_t processed = 0;
  std::uint64_t dropped = 0;
  std::uint64_t badFrames = 0;
  std::uint64_t sourceErrors = 0;
  RunningStat arrivalToSinksDoneMs;
  RunningStat captureToSinksDoneMs;  // empty unless the source's clock is CLOCK_MONOTONIC
  std::vector<StageStat> stages;     // the pipeline's stages, then "sinks"
  std::vector<std::string> notes;    // the sinks' (sink.h: "recording to runs/x.vem"), at the end

  [[nodiscard]] double framesPerSecond() const {
    return elapsedS > 0.0 ? double(processed) / elapsedS : 0.0;
  }
};

// One line: "<label> 5.0 s: 150 in, 150 processed (30.0 frames/s), 0 dropped, 0 bad, 0 source
// errors; latency from arrival to sinks done 3.21 ms mean, 5.10 max[; from capture to sinks done
// ...]; stages us
// mean/max: calibrate 901/1210, ..., sinks 12/40[; recording to runs/x.vem]".
[[nodiscard]] std::string formatReport(const LoopReport& report, const std::string& label);

class LoopStatistics {
 public:
  explicit LoopStatistics(std::int64_t startNs);

  void frameProcessed(const ProcessedFrame& frame, double sinksMicros, std::int64_t lightsOutNs,
                      bool liveClock);
  void frameRefused() {
    ++window_.badFrames;
    ++total_.badFrames;
  }

  // The window since the last call (or the start), then a new window begins at nowNs.
  // `queue` and `sourceErrors` are the running totals; the window gets their increase.
  [[nodiscard]] LoopReport takeWindow(std::int64_t nowNs, const util::QueueCounters& queue,
                                      std::uint64_t sourceErrors);
  // The whole run so far.
  [[nodiscard]] LoopReport totals(std::int64_t nowNs, const util::QueueCounters& queue,
                                  std::uint64_t sourceErrors) const;

  [[nodiscard]] std::uint64_t processed() const { return total_.processed; }

 private:
  static void add(LoopReport& report, const ProcessedFrame& frame, double sinksMicros,
                  std::int64_t lightsOutNs, bool liveClock);

  std::int64_t startNs_;
  std::int64_t windowStartNs_;
  util::QueueCounters windowStartQueue_;
  std::uint64_t windowStartSourceErrors_ = 0;
  LoopReport window_;
  LoopReport total_;
};

}  // namespace vem::vemd
