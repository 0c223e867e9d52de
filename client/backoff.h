// Backoff: the delays between a client's connection attempts. Exponential: the first retry waits
// `initial` (100 ms), each further one twice the last, capped at `max` (5 s); reset() after a
// connection succeeded starts again from `initial`. Pure value type; not thread-safe.
#pragma once

#include <chrono>

namespace vem::client {

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

}  // namespace vem::client
