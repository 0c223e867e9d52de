#include "util/backoff.h"

#include <algorithm>

namespace vem::util {

Backoff::Backoff(std::chrono::milliseconds initial, std::chrono::milliseconds max)
    : initial_(initial), max_(std::max(initial, max)), next_(initial) {}

std::chrono::milliseconds Backoff::next() {
  const std::chrono::milliseconds delay = next_;
  next_ = std::min(next_ * 2, max_);
  return delay;
}

void Backoff::reset() { next_ = initial_; }

}  // namespace vem::util
