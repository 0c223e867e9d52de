// WakeEvent: an eventfd one thread signals to cut another thread's poll(2) short
// (FrameSource::interrupt). A signal sent while nobody waits stays pending until consumed, so it
// is never lost; consume() takes every pending signal at once.
#pragma once

#include "util/unique_fd.h"

namespace vem::cameras {

class WakeEvent {
 public:
  WakeEvent();  // aborts when the kernel refuses an eventfd (out of file descriptors)

  void signal();  // any thread
  // True when at least one signal was pending (and clears them all). Does not block.
  bool consume();
  [[nodiscard]] int fd() const { return fd_.get(); }  // readable while a signal is pending

 private:
  util::UniqueFd fd_;
};

}  // namespace vem::cameras
