// FrameIdUnwrapper: turns the frame ids a GenICam camera stamps (GigE Vision 1.x: 16 bits, 1 to
// 65535, wrapping to 1 since 0 is invalid; GigE Vision 2 extended ids and USB3 Vision: 64 bits)
// into vemd's seq, strictly increasing for the life of the source. Pure.
//
// - The first id after construction or restart() gives `nextSeq` (the gap across a reopen is
//   unknown, so it counts as none).
// - Later ids advance seq by their distance from the previous id, across a 16-bit wrap too;
//   `skipped` tells how many ids were jumped over (frames lost before vemd saw them).
// - An id that repeats or goes backwards without a wrap (the camera restarted its counter) is
//   taken as the next frame: seq + 1, nothing skipped.
#pragma once

#include <cstdint>
#include <optional>

namespace vem::cameras {

class FrameIdUnwrapper {
 public:
  struct Step {
    std::uint64_t seq = 0;
    std::uint64_t skipped = 0;
  };

  [[nodiscard]] Step next(std::uint64_t frameId);
  // The camera was reopened: the next id starts afresh, one past the last seq.
  void restart() { lastId_.reset(); }

 private:
  std::optional<std::uint64_t> lastId_;
  std::uint64_t nextSeq_ = 0;
};

}  // namespace vem::cameras
