// SinkSet: the configured sinks (sink.h), fed one after the other on the processing thread. A sink
// that fails is closed and dropped at once, and its failure is handed back once, so the daemon
// logs it once and keeps feeding the others.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frames/processed_frame.h"
#include "frames/sink.h"

namespace vem::vemd {

struct DroppedSink {
  std::string name;
  std::string message;
};

class SinkSet {
 public:
  SinkSet() = default;
  explicit SinkSet(std::vector<std::unique_ptr<Sink>> sinks) : sinks_(std::move(sinks)) {}

  // Feeds `frame` to every sink; returns the sinks that failed now (and are gone).
  [[nodiscard]] std::vector<DroppedSink> consume(const ProcessedFrame& frame);
  // Closes every sink (flush, close and index files) and forgets them; returns the failures.
  [[nodiscard]] std::vector<DroppedSink> closeAll();

  [[nodiscard]] std::size_t size() const { return sinks_.size(); }
  [[nodiscard]] std::vector<std::string> names() const;
  // The sinks' notes (Sink::note), those that have one, in order.
  [[nodiscard]] std::vector<std::string> notes() const;

 private:
  std::vector<std::unique_ptr<Sink>> sinks_;
};

}  // namespace vem::vemd
