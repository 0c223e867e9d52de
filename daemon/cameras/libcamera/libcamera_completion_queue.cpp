#include "cameras/libcamera/libcamera_completion_queue.h"

namespace vem::cameras {

void LibcameraCompletionQueue::requestCompleted(const LibcameraCompletion& completion) {
  {
    std::lock_guard lock(mutex_);
    completions_.push_back(completion);
  }
  wake_.notify_one();
}

void LibcameraCompletionQueue::disconnected() {
  {
    std::lock_guard lock(mutex_);
    disconnected_ = true;
  }
  wake_.notify_one();
}

LibcameraCompletionQueue::Waited LibcameraCompletionQueue::waitFor(
    std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  const bool woken = wake_.wait_for(
      lock, timeout, [this] { return interrupted_ || !completions_.empty() || disconnected_; });
  if (!woken) return {Wake::Timeout, {}};
  if (interrupted_) {
    interrupted_ = false;
    return {Wake::Interrupted, {}};
  }
  if (!completions_.empty()) {
    Waited out{Wake::Completion, completions_.front()};
    completions_.pop_front();
    return out;
  }
  return {Wake::Disconnected, {}};
}

void LibcameraCompletionQueue::interrupt() {
  {
    std::lock_guard lock(mutex_);
    interrupted_ = true;
  }
  wake_.notify_all();
}

void LibcameraCompletionQueue::clear() {
  std::lock_guard lock(mutex_);
  completions_.clear();
  disconnected_ = false;
}

}  // namespace vem::cameras
