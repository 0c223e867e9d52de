// buildDaemon: from a configuration to the parts runDaemonLoop drives, in the order they depend
// on each other: the source (which brings the camera and its calibration), the pipeline built
// from that calibration, then the sinks (a recording's header needs the camera). Each step that
// fails gives one sentence and builds nothing further.
//
// Start-up can be stopped: `stopRequested` (a signal's flag, in vemd) is asked between the steps
// and between the rows of the polar remap, the one step whose time grows with the settings
// (docs/vemd.md, "Limits"). When it answers true, buildDaemon closes what it opened (a recording
// already created gets its index) and fails with StartupFailure::Cause::Stopped. Once the source
// is open, frames that queue_depth would let pile up beyond kFrameMemoryBudgetBytes are refused.
#pragma once

#include <cstdint>
#include <expected>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frames/frame_source.h"
#include "vemd/daemon_loop.h"
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

// Sinks from outside vem_daemon (the stream server's, vemd/stream_wiring.h), made once the
// source is known; they run after the configured ones. A failure stops the build like any other.
using ExtraSinks = std::function<std::expected<void, std::string>(
    const SourceDescription& source, std::vector<std::unique_ptr<Sink>>& sinks)>;

// Asked between start-up steps and pieces of long ones; true: stop starting. vemd's also tells
// systemd that start-up makes progress (service_observer.h).
using StopCheck = std::function<bool()>;

struct StartupFailure {
  enum class Cause { Failed, Stopped };
  Cause cause = Cause::Failed;
  std::string message;  // one sentence
};

[[nodiscard]] std::expected<Daemon, StartupFailure> buildDaemon(
    const VemdConfig& config, const ExtraSinks& extraSinks = {},
    const StopCheck& stopRequested = {});

// A configured output (a sink's file, the stream server's port) that cannot open, as one sentence:
// `problem` and that vemd stops without it (the flag and key that would let it run)...
[[nodiscard]] std::string missingOutputRefused(std::string_view problem);
// ...or, with output.allow_missing, that it runs without it (a warning).
[[nodiscard]] std::string missingOutputAllowed(std::string_view problem);

// The most bytes of frames vemd may hold at once (docs/vemd.md, "Limits").
inline constexpr std::uint64_t kFrameMemoryBudgetBytes = std::uint64_t(1) << 30;

// The pieces, for tests.
[[nodiscard]] LoopOptions loopOptions(const VemdConfig& config);
// Frames vemd may hold at once with this queue depth: the queue, as many recycled spares plus two,
// the frame being processed and the one being captured.
[[nodiscard]] std::uint64_t framesHeld(std::size_t queueDepth);
// Why the source's frames with source.queue_depth would take more than kFrameMemoryBudgetBytes,
// in one sentence; nullopt when they fit.
[[nodiscard]] std::optional<std::string> frameMemoryProblem(const SourceDescription& source,
                                                            std::size_t queueDepth);
[[nodiscard]] SinkConfig sinkConfig(const OutputConfig& output);
[[nodiscard]] RecordingContext recordingContext(const SourceDescription& source);

}  // namespace vem::vemd
