#include "stream/stream_control.h"

#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/fir_design.h"
#include "frames/frame_source.h"
#include "util/printable.h"

namespace vem::stream {

namespace {

constexpr std::int64_t kStalledAfterNs = 2'000'000'000;

// The source's state for Status: the capture thread's current failure when there is one;
// otherwise TIMEOUT when no frame was processed for kStalledAfterNs (a source that blocks).
SourceState sourceState(const LoopCounters& counters, std::int64_t nowNs) {
  if (counters.sourceFailure) {
    switch (*counters.sourceFailure) {
      case SourceErrorCause::EndOfStream: return SOURCE_STATE_ENDED;
      case SourceErrorCause::NoDevice: return SOURCE_STATE_NO_DEVICE;
      case SourceErrorCause::Timeout: return SOURCE_STATE_TIMEOUT;
      case SourceErrorCause::BadFrame: return SOURCE_STATE_NO_SIGNAL;
    }
  }
  const bool stalled =
      counters.lastProcessedNs == 0 || nowNs - counters.lastProcessedNs > kStalledAfterNs;
  return stalled ? SOURCE_STATE_TIMEOUT : SOURCE_STATE_OK;
}

}  // namespace

StreamControl::StreamControl(Publisher& server, StreamSink& sink, RecordingSwitch* recorder,
                             StreamIdentity identity, std::int64_t statusEveryNs)
    : server_(server),
      sink_(sink),
      recorder_(recorder),
      identity_(std::move(identity)),
      statusEveryNs_(statusEveryNs) {}

void StreamControl::betweenFrames(PipelineControl& pipeline, const LoopCounters& counters) {
  for (PendingControl& pending : server_.takeControls()) {
    const std::string problem = apply(pipeline, pending.command);
    ControlReply reply;
    reply.set_request_id(pending.requestId);
    reply.set_ok(problem.empty());
    reply.set_message(problem);
    server_.reply(pending.connection, reply);
  }
  if (recorder_ != nullptr) {
    if (auto failure = recorder_->takeFailure()) {
      spdlog::error("stream: the recording started by a client stopped: {}",
                    util::printable(*failure));
    }
  }
  sink_.setStamp({pipeline.filterDelayFrames()});
  const std::int64_t nowNs = monotonicNowNs();
  if (nowNs >= nextStatusNs_) {
    publishStatus(pipeline, counters, nowNs);
    nextStatusNs_ = nowNs + statusEveryNs_;
  }
}

std::string StreamControl::apply(PipelineControl& pipeline, const Control& command) {
  ProcessingOptions options = pipeline.options();
  switch (command.action_case()) {
    case Control::kSetLightCount:
      options.lightCount = command.set_light_count();
      return reconfigure(pipeline, options, fmt::format("{} lights", options.lightCount));
    case Control::kSetClusterBudget:
      options.clustering = command.set_cluster_budget() > 0;
      if (options.clustering) options.clusterBudget = int(command.set_cluster_budget());
      return reconfigure(pipeline, options,
                         options.clustering
                             ? fmt::format("clustering toward {} lights", options.clusterBudget)
                             : std::string("clustering off"));
    case Control::kSetFilter:
      for (FilterPreset preset : kAllPresets) {
        if (command.set_filter() == presetName(preset)) {
          options.filter = preset;
          return reconfigure(pipeline, options, fmt::format("filter {}", presetName(preset)));
        }
      }
      return fmt::format(
          "there is no filter preset \"{}\" (\"none\", \"paper9\", \"equiripple5\", "
          "\"minphase9\")",
          util::printable(command.set_filter()));
    case Control::kStartRecording: {
      if (recorder_ == nullptr) return "this daemon cannot record for clients";
      auto started = recorder_->start(command.start_recording().name());
      if (!started) return started.error();
      spdlog::info("stream: a client started recording into {}",
                   util::printable(started->string()));
      return {};
    }
    case Control::kStopRecording: {
      if (recorder_ == nullptr) return "no recording is running";
      auto stopped = recorder_->stop();
      if (!stopped) return stopped.error();
      spdlog::info("stream: a client stopped the recording {}",
                   util::printable(stopped->string()));
      return {};
    }
    case Control::ACTION_NOT_SET: break;
  }
  return "the control message has no action";
}

std::string StreamControl::reconfigure(PipelineControl& pipeline, const ProcessingOptions& options,
                                       const std::string& change) {
  if (options == pipeline.options()) return {};
  if (auto done = pipeline.reconfigure(options); !done) return done.error();
  spdlog::info("stream: a client set {}", change);
  return {};
}

void StreamControl::publishStatus(const PipelineControl& pipeline, const LoopCounters& counters,
                                  std::int64_t nowNs) {
  const SinkWindow window = sink_.takeWindow(nowNs);
  const ProcessingOptions& options = pipeline.options();
  Status status;
  status.set_source(identity_.source);
  status.set_state(sourceState(counters, nowNs));
  status.set_frame_rate_hz(window.elapsedS > 0.0 ? double(window.frames) / window.elapsedS : 0.0);
  status.set_frames_processed(counters.processed);
  status.set_frames_dropped(counters.dropped);
  status.set_frames_refused(counters.refused);
  status.set_latency_median_ms(window.latencyMedianMs);
  status.set_calibration_id(identity_.calibrationId);
  status.set_light_count(std::uint32_t(options.lightCount));
  status.set_clustering(options.clustering);
  status.set_filter(presetName(options.filter));
  status.set_recording(recorder_ != nullptr && recorder_->recording());
  server_.publishStatus(status);
  ++statusesPublished_;
}

}  // namespace vem::stream
