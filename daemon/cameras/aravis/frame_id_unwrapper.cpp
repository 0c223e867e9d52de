#include "cameras/aravis/frame_id_unwrapper.h"

namespace vem::cameras {

namespace {

constexpr std::uint64_t kMaxShortId = 0xffff;
// A 16-bit counter wrapped when it went from the top quarter to the bottom quarter.
constexpr std::uint64_t kWrapWindow = 0x4000;

std::uint64_t distance(std::uint64_t last, std::uint64_t id) {
  if (id > last) return id - last;
  const bool shortIds = last <= kMaxShortId && id <= kMaxShortId;
  if (shortIds && last > kMaxShortId - kWrapWindow && id < kWrapWindow) {
    return (kMaxShortId - last) + id;  // ids skip 0: 65535 -> 1 is one step
  }
  return 1;  // a restarted counter
}

}  // namespace

FrameIdUnwrapper::Step FrameIdUnwrapper::next(std::uint64_t frameId) {
  const std::uint64_t step = lastId_ ? distance(*lastId_, frameId) : 1;
  if (lastId_) nextSeq_ += step - 1;
  lastId_ = frameId;
  return Step{nextSeq_++, step - 1};
}

}  // namespace vem::cameras
