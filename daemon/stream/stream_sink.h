// StreamSink: vemd's processed frames to the stream server (stream_server.h), on the processing
// thread like every sink (frames/sink.h).
//
// - Per frame, the light frame message is built and serialized once (frame_encoding.h: exactly
//   the lights the JSON-lines sink writes) and handed to the server, which never waits for a
//   client.
// - Cube maps are made only while some client subscribed to them: per distinct variant (face
//   size, levels, preview) at the highest rate asked for it. This sink only decides which
//   variants are due in a frame and hands the frame's polar map to the CubemapWorker, which
//   builds them on its own thread (cubemap_worker.h); the processing thread never builds one.
// - consume() never fails (a network client cannot fail vemd), so the sink set never drops it and
//   StreamControl may keep borrowing it.
// Times: *UnixNs on CLOCK_REALTIME, latency and due times on CLOCK_MONOTONIC.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frames/sink.h"
#include "stream/cubemap_worker.h"
#include "stream/publisher.h"
#include "stream/subscription.h"

namespace vem::stream {

struct StreamSinkOptions {
  int zstdLevel = 3;
  int previewWidthPx = 256;
};

// What the sink needs from the pipeline, refreshed between frames (stream_control.h).
struct ProcessingStamp {
  double filterDelayFrames = 0.0;
};

// Frames and latency since the last takeWindow().
struct SinkWindow {
  std::uint64_t frames = 0;
  double elapsedS = 0.0;
  double latencyMedianMs = 0.0;  // arrival in vemd to the light frame handed to the server
};

class StreamSink final : public Sink {
 public:
  StreamSink(Publisher& server, StreamSinkOptions options);

  [[nodiscard]] std::string name() const override { return "stream"; }
  [[nodiscard]] std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, SinkFailure> close() override { return {}; }
  [[nodiscard]] std::string note() const override { return server_.note(); }

  void setStamp(const ProcessingStamp& stamp) { stamp_ = stamp; }
  [[nodiscard]] SinkWindow takeWindow(std::int64_t nowMonotonicNs);

  [[nodiscard]] std::uint64_t framesPublished() const { return framesPublished_; }
  [[nodiscard]] CubemapWorkerCounters cubemapCounters() const { return worker_.counters(); }
  // Waits until the cube-map worker has built everything offered so far (tests).
  [[nodiscard]] bool waitForCubemaps(std::int64_t timeoutNs) const {
    return worker_.waitIdle(timeoutNs);
  }
  [[nodiscard]] std::uint32_t lightsInLastFrame() const { return lightsInLastFrame_; }

 private:
  void publishCubemaps(const ProcessedFrame& frame, std::int64_t nowNs);

  Publisher& server_;
  StreamSinkOptions options_;
  ProcessingStamp stamp_;
  std::map<CubeVariant, std::int64_t> nextCubemapDueNs_;
  std::vector<double> windowLatenciesMs_;
  std::int64_t windowStartNs_ = 0;
  std::uint64_t windowFrames_ = 0;
  std::uint64_t framesPublished_ = 0;
  std::uint32_t lightsInLastFrame_ = 0;
  CubemapWorker worker_;  // last: its thread stops before the rest goes
};

}  // namespace vem::stream
