// StreamControl: the stream's work between frames on vemd's processing thread
// (LoopControl, daemon_loop.h): applies the control messages clients sent (they wait in the
// server's inbox), refreshes what the stream sink stamps on light frames, and publishes a status
// about once a second.
//
// Control: set_light_count, set_cluster_budget (0: clustering off) and set_filter reconfigure the
// pipeline (PipelineControl::reconfigure: only what changed is reset); start_recording and
// stop_recording switch the RecordingSwitch. Each request gets one ControlReply (ok, or why not in
// one sentence) and each applied change one log line.
//
// Borrows the server, the sink and the switch: the sink and the switch never fail, so the sink set
// keeps them until the loop ends, and betweenFrames is not called after that.
#pragma once

#include <cstdint>
#include <string>

#include "frames/loop_control.h"
#include "stream/publisher.h"
#include "stream/recording_switch.h"
#include "stream/stream_sink.h"

namespace vem::stream {

struct StreamIdentity {
  std::string source;         // the source spec
  std::string calibrationId;  // stream_setup.h calibrationId
};

class StreamControl final : public LoopControl {
 public:
  // `recorder` may be null (no recording by control: start_recording is refused).
  StreamControl(Publisher& server, StreamSink& sink, RecordingSwitch* recorder,
                StreamIdentity identity, std::int64_t statusEveryNs = 1'000'000'000);

  void betweenFrames(PipelineControl& pipeline, const LoopCounters& counters) override;

  [[nodiscard]] std::uint64_t statusesPublished() const { return statusesPublished_; }

 private:
  // Empty when applied, else why not.
  std::string apply(PipelineControl& pipeline, const Control& command);
  std::string reconfigure(PipelineControl& pipeline, const ProcessingOptions& options,
                          const std::string& change);
  void publishStatus(const PipelineControl& pipeline, const LoopCounters& counters,
                     std::int64_t nowNs);

  Publisher& server_;
  StreamSink& sink_;
  RecordingSwitch* recorder_;
  StreamIdentity identity_;
  std::int64_t statusEveryNs_;
  std::int64_t nextStatusNs_ = 0;
  std::uint64_t statusesPublished_ = 0;
};

}  // namespace vem::stream
