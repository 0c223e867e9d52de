#include "stream/outbox.h"

#include <utility>

namespace vem::stream {

void Outbox::putLights(SharedBytes message, std::uint64_t alreadySkipped) {
  skippedLights_ += alreadySkipped;
  if (lights_) ++skippedLights_;
  lights_ = std::move(message);
}

bool Outbox::putReply(SharedBytes message) {
  if (replies_.size() >= kMaxReplies) return false;
  replies_.push_back(std::move(message));
  return true;
}

SharedBytes Outbox::next() {
  if (!replies_.empty()) {
    SharedBytes reply = std::move(replies_.front());
    replies_.pop_front();
    return reply;
  }
  const bool othersFirst = lastWasLights_ && (environment_ || status_);
  if (lights_ && !othersFirst) {
    lastWasLights_ = true;
    ++sentLights_;
    return std::exchange(lights_, nullptr);
  }
  lastWasLights_ = false;
  if (environment_) return std::exchange(environment_, nullptr);
  return std::exchange(status_, nullptr);
}

}  // namespace vem::stream
