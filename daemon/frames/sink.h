// Sink: where vemd's processed frames go (a JSON-lines light file, the recorder, the preview
// image, the stream server). Sinks run on the processing thread, one after the other, in the
// order configured; a slow sink slows processing (the capture queue then drops the oldest frames,
// counted) but never the capture thread.
//
// A sink that fails (disk full, a closed pipe) reports it as a value and goes quiet: vemd logs the
// error once, keeps running and keeps feeding the other sinks.
#pragma once

#include <expected>
#include <string>

#include "frames/processed_frame.h"

namespace vem {

struct SinkFailure {
  std::string message;  // one sentence naming the sink, the file and the cause
};

class Sink {
 public:
  virtual ~Sink() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  // A few words for the start-up log and every statistics line, naming what the sink writes
  // where a user looks for it ("recording to runs/vemd-20261203T101500Z.vem"); empty: nothing.
  [[nodiscard]] virtual std::string note() const { return {}; }
  // Called once per processed frame, in order.
  [[nodiscard]] virtual std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) = 0;
  // Called once at shutdown: flush, close and index files.
  [[nodiscard]] virtual std::expected<void, SinkFailure> close() = 0;
};

}  // namespace vem
