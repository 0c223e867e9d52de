// FrameSequence: turns the driver's v4l2_buffer::sequence into vemd's frame seq
// (frames/captured_frame.h): strictly increasing across the whole life of a source, with the
// driver's gaps kept (a gap of k means k - 1 frames lost before we saw them) and counted.
//
// - The first frame gets seq 0.
// - A driver sequence that does not move forward (the driver restarted counting, after a reopen or
//   STREAMON) continues at the previous seq + 1 with nothing counted lost; restart() says that the
//   next sequence starts a new count on purpose.
// - Frames the backend drops itself (short, flagged corrupt) still take their seq, so consumers
//   see them as lost too; the backend counts them apart.
// Pure value type.
#pragma once

#include <cstdint>
#include <optional>

namespace vem::cameras {

class FrameSequence {
 public:
  // The seq of the frame the driver numbered `driverSequence`.
  [[nodiscard]] std::uint64_t next(std::uint32_t driverSequence) {
    std::uint64_t step = 1;
    if (lastDriver_ && !restarted_) {
      const std::uint32_t delta = driverSequence - *lastDriver_;  // wraps at 2^32
      if (delta >= 1 && delta < (1u << 31)) step = delta;
    }
    restarted_ = false;
    lost_ += step - 1;
    lastDriver_ = driverSequence;
    const std::uint64_t seq = lastSeq_ ? *lastSeq_ + step : 0;
    lastSeq_ = seq;
    return seq;
  }
  void restart() { restarted_ = true; }
  [[nodiscard]] std::uint64_t lost() const { return lost_; }

 private:
  std::optional<std::uint32_t> lastDriver_;
  std::optional<std::uint64_t> lastSeq_;
  bool restarted_ = false;
  std::uint64_t lost_ = 0;
};

}  // namespace vem::cameras
