#include "vemd/sink_set.h"

#include <utility>

namespace vem::vemd {

std::vector<DroppedSink> SinkSet::consume(const ProcessedFrame& frame) {
  std::vector<DroppedSink> dropped;
  for (auto it = sinks_.begin(); it != sinks_.end();) {
    auto done = (*it)->consume(frame);
    if (done) {
      ++it;
      continue;
    }
    dropped.push_back({(*it)->name(), std::move(done.error().message)});
    (void)(*it)->close();  // best effort: a recorder still writes its index
    it = sinks_.erase(it);
  }
  return dropped;
}

std::vector<DroppedSink> SinkSet::closeAll() {
  std::vector<DroppedSink> failed;
  for (auto& sink : sinks_) {
    if (auto closed = sink->close(); !closed) {
      failed.push_back({sink->name(), std::move(closed.error().message)});
    }
  }
  sinks_.clear();
  return failed;
}

std::vector<std::string> SinkSet::names() const {
  std::vector<std::string> out;
  for (const auto& sink : sinks_) out.push_back(sink->name());
  return out;
}

std::vector<std::string> SinkSet::notes() const {
  std::vector<std::string> out;
  for (const auto& sink : sinks_) {
    if (std::string note = sink->note(); !note.empty()) out.push_back(std::move(note));
  }
  return out;
}

}  // namespace vem::vemd
