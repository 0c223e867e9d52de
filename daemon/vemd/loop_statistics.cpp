#include "vemd/loop_statistics.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>

namespace vem::vemd {

void RunningStat::add(double value) {
  max = count == 0 ? value : std::max(max, value);
  sum += value;
  ++count;
}

std::string formatReport(const LoopReport& r, const std::string& label) {
  std::string line = fmt::format(
      "{} {:.1f} s: {} in, {} processed ({:.1f} frames/s), {} dropped, {} bad, {} source errors",
      label, r.elapsedS, r.framesIn, r.processed, r.framesPerSecond(), r.dropped, r.badFrames,
      r.sourceErrors);
  if (r.arrivalToSinksDoneMs.count > 0) {
    fmt::format_to(std::back_inserter(line),
                   "; latency from arrival to sinks done {:.2f} ms mean, {:.2f} max",
                   r.arrivalToSinksDoneMs.mean(), r.arrivalToSinksDoneMs.max);
  }
  if (r.captureToSinksDoneMs.count > 0) {
    fmt::format_to(std::back_inserter(line),
                   "; from capture to sinks done {:.2f} ms mean, {:.2f} max",
                   r.captureToSinksDoneMs.mean(), r.captureToSinksDoneMs.max);
  }
  if (!r.stages.empty() && r.processed > 0) {
    line += "; stages us mean/max:";
    for (const StageStat& s : r.stages) {
      fmt::format_to(std::back_inserter(line), " {} {:.0f}/{:.0f}", s.stage, s.micros.mean(),
                     s.micros.max);
    }
  }
  for (const std::string& note : r.notes) fmt::format_to(std::back_inserter(line), "; {}", note);
  return line;
}

LoopStatistics::LoopStatistics(std::int64_t startNs) : startNs_(startNs), windowStartNs_(startNs) {}

void LoopStatistics::add(LoopReport& report, const ProcessedFrame& frame, double sinksMicros,
                         std::int64_t lightsOutNs, bool liveClock) {
  ++report.processed;
  if (report.stages.empty()) {
    for (const StageTiming& t : frame.timings) report.stages.push_back({t.stage, {}});
    report.stages.push_back({"sinks", {}});
  }
  for (std::size_t i = 0; i < frame.timings.size() && i < report.stages.size(); ++i) {
    report.stages[i].micros.add(frame.timings[i].micros);
  }
  report.stages.back().micros.add(sinksMicros);
  report.arrivalToSinksDoneMs.add(double(lightsOutNs - frame.captured->arrivalNs) * 1e-6);
  if (liveClock)
    report.captureToSinksDoneMs.add(double(lightsOutNs - frame.captured->captureTsNs) * 1e-6);
}

void LoopStatistics::frameProcessed(const ProcessedFrame& frame, double sinksMicros,
                                    std::int64_t lightsOutNs, bool liveClock) {
  add(window_, frame, sinksMicros, lightsOutNs, liveClock);
  add(total_, frame, sinksMicros, lightsOutNs, liveClock);
}

LoopReport LoopStatistics::takeWindow(std::int64_t nowNs, const util::QueueCounters& queue,
                                      std::uint64_t sourceErrors) {
  LoopReport report = std::move(window_);
  report.elapsedS = double(nowNs - windowStartNs_) * 1e-9;
  report.framesIn = queue.pushed - windowStartQueue_.pushed;
  report.dropped = queue.dropped - windowStartQueue_.dropped;
  report.sourceErrors = sourceErrors - windowStartSourceErrors_;
  window_ = LoopReport{};
  windowStartNs_ = nowNs;
  windowStartQueue_ = queue;
  windowStartSourceErrors_ = sourceErrors;
  return report;
}

LoopReport LoopStatistics::totals(std::int64_t nowNs, const util::QueueCounters& queue,
                                  std::uint64_t sourceErrors) const {
  LoopReport report = total_;
  report.elapsedS = double(nowNs - startNs_) * 1e-9;
  report.framesIn = queue.pushed;
  report.dropped = queue.dropped;
  report.sourceErrors = sourceErrors;
  return report;
}

}  // namespace vem::vemd
