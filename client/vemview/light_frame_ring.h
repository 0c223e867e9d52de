// LightFrameRing: the light frames vemview has seen lately, so that a plate picture is composited
// with the light frame nearest to it in time (issue 21, "time alignment"), not merely the newest.
// Both carry capture times on the system clock (a live camera's pictures, vemd's stream); a frame
// without one is never chosen by time.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>

#include "client/vemview/light_input.h"

namespace vem::view {

class LightFrameRing {
 public:
  explicit LightFrameRing(std::size_t capacity = 16);
  // Keeps `frame` unless it is the newest already (same seq); the oldest goes past capacity.
  void push(const InputFrame& frame);
  [[nodiscard]] bool empty() const { return frames_.empty(); }
  [[nodiscard]] const InputFrame& newest() const { return frames_.back(); }

  struct Choice {
    const InputFrame* frame = nullptr;  // never null once a frame was pushed
    bool withinWindow = false;          // |capture - pictureTime| <= windowSec
  };
  // The frame whose capture time is nearest to pictureUnixSec, when it lies within windowSec of
  // it; otherwise the newest (withinWindow false). Needs a frame pushed.
  [[nodiscard]] Choice nearest(double pictureUnixSec, double windowSec) const;

 private:
  std::size_t capacity_;
  std::deque<InputFrame> frames_;
};

}  // namespace vem::view
