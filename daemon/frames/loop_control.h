// LoopControl: work done between frames on vemd's processing thread (vemd/daemon_loop.h), and what
// it may see and change: the loop's running totals (LoopCounters) and the pipeline's options
// (PipelineControl). The stream's control messages (stream/stream_control.h) come in this way,
// without the stream knowing vemd's loop or pipeline.
//
// - betweenFrames is called on the processing thread before the first frame, after every frame and
//   at least every vemd::kPollInterval, never during a frame.
// - PipelineControl::reconfigure changes the options between frames, resetting only what changed;
//   it fails, changing nothing, with one sentence naming the option out of range.
#pragma once

#include <cstdint>
#include <expected>
#include <optional>
#include <string>

#include "frames/frame_source.h"
#include "frames/processing_options.h"

namespace vem {

// The loop's running totals, for a LoopControl.
struct LoopCounters {
  std::uint64_t processed = 0;
  std::uint64_t dropped = 0;  // by the queue
  std::uint64_t refused = 0;  // bad frames
  std::uint64_t sourceErrors = 0;
  std::int64_t lastProcessedNs = 0;  // CLOCK_MONOTONIC; 0 before the first frame
  // Why the source gives no frames now (CaptureThread::failure); empty while frames flow.
  std::optional<SourceErrorCause> sourceFailure;
};

// What a LoopControl may do to the pipeline (vemd::Pipeline implements it).
class PipelineControl {
 public:
  virtual ~PipelineControl() = default;
  [[nodiscard]] virtual const ProcessingOptions& options() const = 0;
  [[nodiscard]] virtual std::expected<void, std::string> reconfigure(
      const ProcessingOptions& options) = 0;
  // The temporal filter's group delay, in frames.
  [[nodiscard]] virtual double filterDelayFrames() const = 0;
};

class LoopControl {
 public:
  virtual ~LoopControl() = default;
  virtual void betweenFrames(PipelineControl& pipeline, const LoopCounters& counters) = 0;
};

}  // namespace vem
