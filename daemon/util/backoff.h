// Backoff: the delays between attempts to reach something that failed (a client's connection, a
// camera that went away). Exponential: the first retry waits `initial`, each further one twice
// the last, capped at `max`; reset() after a success starts again from `initial`. Pure value type;
// not thread-safe.
#pragma once

#include <chrono>

namespace vem::util {

class Backoff {
 public:
  explicit Backoff(std::chrono::milliseconds initial = std::chrono::milliseconds(100),
                   std::chrono::milliseconds max = std::chrono::milliseconds(5000));

  // The delay before the next attempt; the one after it will be twice as long (up to max).
  [[nodiscard]] std::chrono::milliseconds next();
  void reset();

 private:
  std::chrono::milliseconds initial_;
  std::chrono::milliseconds max_;
  std::chrono::milliseconds next_;
};

}  // namespace vem::util
