// LibcameraCompletionQueue: hands what a LibcameraCameraPort reports on libcamera's thread
// (completed requests, the camera's disconnection) to the capture thread, through a mutex and a
// condition variable. The capture thread waits in waitFor(); interrupt() (any thread) ends one
// wait, or the next one when nobody waits, so it is never lost.
//
// Completions come out in the order they went in; a disconnection is reported once the
// completions that arrived before it are taken.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>

#include "cameras/libcamera/libcamera_port.h"

namespace vem::cameras {

class LibcameraCompletionQueue final : public LibcameraEvents {
 public:
  enum class Wake { Completion, Disconnected, Interrupted, Timeout };
  struct Waited {
    Wake wake = Wake::Timeout;
    LibcameraCompletion completion;  // when wake == Completion
  };

  void requestCompleted(const LibcameraCompletion& completion) override;
  void disconnected() override;

  [[nodiscard]] Waited waitFor(std::chrono::milliseconds timeout);
  void interrupt();
  // Forgets completions and a disconnection (a camera opened afresh). Keeps an interrupt.
  void clear();

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<LibcameraCompletion> completions_;
  bool disconnected_ = false;
  bool interrupted_ = false;
};

}  // namespace vem::cameras
