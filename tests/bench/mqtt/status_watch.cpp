#include "bench/mqtt/status_watch.h"

#include <chrono>

#include "proto/vem_stream.pb.h"

namespace vem::bench {

StatusDelta operator-(const StatusSample& later, const StatusSample& earlier) {
  StatusDelta d;
  d.seconds = double(later.receivedSteadyNs - earlier.receivedSteadyNs) * 1e-9;
  d.framesProcessed = later.framesProcessed - earlier.framesProcessed;
  d.framesDropped = later.framesDropped - earlier.framesDropped;
  d.publishDropped = later.publishDropped - earlier.publishDropped;
  return d;
}

void StatusWatch::record(std::string_view topic, std::string_view payload) {
  // PREFIX/CAMERA/status: the camera is the level before the last.
  const std::size_t last = topic.rfind('/');
  if (last == std::string_view::npos || topic.substr(last + 1) != "status") return;
  const std::size_t before = topic.rfind('/', last - 1);
  const std::string_view camera =
      topic.substr(before == std::string_view::npos ? 0 : before + 1,
                   last - (before == std::string_view::npos ? 0 : before + 1));
  stream::ServerMessage message;
  if (!message.ParseFromArray(payload.data(), int(payload.size())) || !message.has_status()) {
    return;
  }
  const stream::Status& s = message.status();
  StatusSample sample;
  sample.receivedSteadyNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                std::chrono::steady_clock::now().time_since_epoch())
                                .count();
  sample.framesProcessed = s.frames_processed();
  sample.framesDropped = s.frames_dropped();
  sample.publishDropped = s.publish_dropped();
  sample.offline = s.offline();
  std::lock_guard lock(mutex_);
  latest_[std::string(camera)] = sample;
}

std::optional<StatusSample> StatusWatch::latest(const std::string& cameraId) const {
  std::lock_guard lock(mutex_);
  const auto it = latest_.find(cameraId);
  if (it == latest_.end()) return std::nullopt;
  return it->second;
}

}  // namespace vem::bench
