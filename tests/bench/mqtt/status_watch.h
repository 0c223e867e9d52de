// StatusWatch: the newest Status each camera's vemd published on PREFIX/CAMERA/status (retained,
// about once a second; docs/protocol.md, "MQTT"), as an MQTT subscriber to PREFIX/+/status hands
// them over. Two of them, read at the start and the end of a window, give what vemd did meanwhile:
// the frames it processed, its capture queue dropped and its MQTT publisher dropped.
// Thread-safe.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

namespace vem::bench {

struct StatusSample {
  std::int64_t receivedSteadyNs = 0;  // when it arrived here (steady clock)
  std::uint64_t framesProcessed = 0;
  std::uint64_t framesDropped = 0;   // by vemd's capture queue
  std::uint64_t publishDropped = 0;  // by vemd's MQTT publisher
  bool offline = false;
};

// What vemd did between two of its statuses.
struct StatusDelta {
  double seconds = 0.0;  // between their arrivals
  std::uint64_t framesProcessed = 0;
  std::uint64_t framesDropped = 0;
  std::uint64_t publishDropped = 0;
  [[nodiscard]] double processedHz() const {
    return seconds > 0.0 ? double(framesProcessed) / seconds : 0.0;
  }
};

[[nodiscard]] StatusDelta operator-(const StatusSample& later, const StatusSample& earlier);

class StatusWatch {
 public:
  // One message from PREFIX/CAMERA/status; others, and payloads that are no Status, are ignored.
  void record(std::string_view topic, std::string_view payload);
  // The newest status of `cameraId` so far.
  [[nodiscard]] std::optional<StatusSample> latest(const std::string& cameraId) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, StatusSample, std::less<>> latest_;
};

}  // namespace vem::bench
