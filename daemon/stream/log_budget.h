// LogBudget: one kind of repeating event (a client connected, a handshake timed out, a connection
// refused), logged at a bounded rate. Within each window the first `burst` events are logged one by
// one; the rest are only counted, and once the window is over one line says how many were not
// logged (STYLE.md: repeating events are logged once per change of state, with counts). A flood
// then costs a few lines per window, whatever its rate.
//
// Times are steady-clock nanoseconds passed in. Pure; not thread-safe.
#pragma once

#include <cstdint>

namespace vem::stream {

class LogBudget {
 public:
  LogBudget(std::int64_t windowNs, std::uint32_t burst) : windowNs_(windowNs), burst_(burst) {}

  // Counts an event at `nowNs`; true when it is to be logged on its own.
  [[nodiscard]] bool admit(std::int64_t nowNs) {
    roll(nowNs);
    ++total_;
    if (loggedInWindow_ < burst_) {
      ++loggedInWindow_;
      return true;
    }
    ++suppressed_;
    return false;
  }

  // The count of events not logged one by one in windows that ended by `nowNs` (0: nothing to
  // say); the count starts again.
  [[nodiscard]] std::uint64_t takeSuppressed(std::int64_t nowNs) {
    roll(nowNs);
    const std::uint64_t count = ended_;
    ended_ = 0;
    return count;
  }

  [[nodiscard]] std::uint64_t total() const { return total_; }

 private:
  void roll(std::int64_t nowNs) {
    if (nowNs - windowStartNs_ < windowNs_) return;
    ended_ += suppressed_;
    suppressed_ = 0;
    loggedInWindow_ = 0;
    windowStartNs_ = nowNs;
  }

  std::int64_t windowNs_;
  std::uint32_t burst_;
  std::int64_t windowStartNs_ = INT64_MIN / 2;
  std::uint32_t loggedInWindow_ = 0;
  std::uint64_t suppressed_ = 0;  // in the current window
  std::uint64_t ended_ = 0;       // in windows that ended, not yet taken
  std::uint64_t total_ = 0;
};

}  // namespace vem::stream
