#include "client/vemview/light_frame_ring.h"

#include <cmath>

#include "util/contract.h"

namespace vem::view {

LightFrameRing::LightFrameRing(std::size_t capacity) : capacity_(capacity) {
  VEM_EXPECTS(capacity >= 1);
}

void LightFrameRing::push(const InputFrame& frame) {
  if (!frames_.empty() && frames_.back().seq == frame.seq) return;
  frames_.push_back(frame);
  if (frames_.size() > capacity_) frames_.pop_front();
}

LightFrameRing::Choice LightFrameRing::nearest(double pictureUnixSec, double windowSec) const {
  VEM_EXPECTS(!frames_.empty());
  const InputFrame* best = nullptr;
  double bestGap = 0.0;
  for (const InputFrame& frame : frames_) {
    if (!frame.captureUnixSec) continue;
    const double gap = std::abs(*frame.captureUnixSec - pictureUnixSec);
    if (best == nullptr || gap < bestGap) {
      best = &frame;
      bestGap = gap;
    }
  }
  if (best != nullptr && bestGap <= windowSec) return Choice{best, true};
  return Choice{&frames_.back(), false};
}

}  // namespace vem::view
