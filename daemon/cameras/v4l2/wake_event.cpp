#include "cameras/v4l2/wake_event.h"

#include <sys/eventfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "util/contract.h"

namespace vem::cameras {

WakeEvent::WakeEvent() : fd_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {
  // eventfd fails only when the process or the system is out of descriptors or memory; the cause
  // goes out before the contract line.
  if (!fd_.valid()) std::fprintf(stderr, "WakeEvent: eventfd failed: %s\n", std::strerror(errno));
  VEM_EXPECTS(fd_.valid());
}

void WakeEvent::signal() {
  const std::uint64_t one = 1;
  ssize_t written = 0;
  do {
    written = ::write(fd_.get(), &one, sizeof one);
  } while (written < 0 && errno == EINTR);
  // EAGAIN only when the counter is at its maximum: a signal is pending anyway.
}

bool WakeEvent::consume() {
  std::uint64_t count = 0;
  ssize_t got = 0;
  do {
    got = ::read(fd_.get(), &count, sizeof count);
  } while (got < 0 && errno == EINTR);
  return got == ssize_t(sizeof count) && count > 0;
}

}  // namespace vem::cameras
