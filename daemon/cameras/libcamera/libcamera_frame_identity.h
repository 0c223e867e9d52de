// LibcameraFrameIdentity: the seq and captureTsNs (frames/captured_frame.h) a libcamera completion
// gets. Pure: the clocks are read by the caller.
//
// - seq: FrameMetadata::sequence counts frames per capture session (from start(), wrapping at
//   2^32); vemd's seq counts on across sessions (a camera reopened after an unplug continues where
//   it stopped), so it strictly increases. A jump of the camera's sequence by k > 1 within a
//   session means k - 1 frames were lost before vemd saw them; seq jumps by k too. A sequence that
//   does not increase (repeated or older, more than 2^31 back) is refused.
// - captureTsNs: FrameMetadata::timestamp in nanoseconds on the port's clock, converted to
//   CLOCK_MONOTONIC: a CLOCK_BOOTTIME stamp minus (boottime now - monotonic now), the time the
//   system spent suspended. V4L2 stamps buffers on CLOCK_MONOTONIC already (no conversion).
#pragma once

#include <cstdint>
#include <optional>

#include "cameras/libcamera/libcamera_port.h"

namespace vem::cameras {

struct NumberedFrame {
  std::uint64_t seq = 0;
  std::uint64_t lost = 0;  // frames skipped since the previous one of this session
};

class LibcameraFrameNumbering {
 public:
  // A new capture session: the camera's next sequence number starts a fresh count.
  void startSession() { sessionStarted_ = false; }
  // vemd's seq for the camera's `sequence`, or nullopt when it does not increase.
  [[nodiscard]] std::optional<NumberedFrame> accept(std::uint32_t sequence);

 private:
  bool sessionStarted_ = false;
  std::uint32_t lastSequence_ = 0;
  std::uint64_t nextSeq_ = 0;
};

// `timestampNs` on `clock`, given that clock's and CLOCK_MONOTONIC's readings taken together.
[[nodiscard]] std::int64_t monotonicCaptureNs(std::uint64_t timestampNs, LibcameraClock clock,
                                              std::int64_t clockNowNs, std::int64_t monotonicNowNs);

}  // namespace vem::cameras
