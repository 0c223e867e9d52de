#include "cameras/libcamera/libcamera_frame_identity.h"

namespace vem::cameras {

std::optional<NumberedFrame> LibcameraFrameNumbering::accept(std::uint32_t sequence) {
  if (!sessionStarted_) {
    sessionStarted_ = true;
    lastSequence_ = sequence;
    return NumberedFrame{nextSeq_++, 0};
  }
  const std::uint32_t step = sequence - lastSequence_;  // modulo 2^32: wraps cleanly
  if (step == 0 || step > (std::uint32_t(1) << 31)) return std::nullopt;
  lastSequence_ = sequence;
  const std::uint64_t seq = nextSeq_ - 1 + step;
  nextSeq_ = seq + 1;
  return NumberedFrame{seq, std::uint64_t(step) - 1};
}

std::int64_t monotonicCaptureNs(std::uint64_t timestampNs, LibcameraClock clock,
                                std::int64_t clockNowNs, std::int64_t monotonicNowNs) {
  const auto stamp = std::int64_t(timestampNs);
  if (clock == LibcameraClock::Monotonic) return stamp;
  return stamp - (clockNowNs - monotonicNowNs);
}

}  // namespace vem::cameras
