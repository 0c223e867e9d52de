// buildDaemon: from a configuration to the parts runDaemonLoop drives, in the order they depend
// on each other: the source (which brings the camera and its calibration), the pipeline built
// from that calibration, then the sinks (a recording's header needs the camera). Each step that
// fails gives one sentence and builds nothing further.
#pragma once

#include <expected>
#include <memory>
#include <optional>
#include <string>

#include "vemd/daemon_loop.h"
#include "vemd/frame_source.h"
#include "vemd/pipeline.h"
#include "vemd/sink_set.h"
#include "vemd/sinks/recording_context.h"
#include "vemd/sinks/sink_factory.h"
#include "vemd/vemd_config.h"

namespace vem::vemd {

struct Daemon {
  std::unique_ptr<FrameSource> source;
  std::optional<Pipeline> pipeline;  // always set by buildDaemon
  SinkSet sinks;
  LoopOptions loop;
};

[[nodiscard]] std::expected<Daemon, std::string> buildDaemon(const VemdConfig& config);

// The pieces, for tests.
[[nodiscard]] LoopOptions loopOptions(const VemdConfig& config);
[[nodiscard]] SinkConfig sinkConfig(const OutputConfig& output,
                                    const ProcessingOptions& processing);
[[nodiscard]] RecordingContext recordingContext(const SourceDescription& source);

}  // namespace vem::vemd
