// The physical floor under the fan-out figures: the one-way latency of one message of `bytes` over
// a TCP connection on 127.0.0.1 (TCP_NODELAY, as vemd's stream and Mosquitto use), from the
// sender's write to the receiver holding all of it, both CLOCK_REALTIME, between two threads of
// this process; one message at a time (the receiver answers one byte before the next goes), so no
// queueing is measured. A path through a broker crosses loopback twice.
#pragma once

#include <cstddef>
#include <expected>
#include <string>

namespace vem::bench {

struct LoopbackLatency {
  std::size_t bytes = 0;
  std::size_t messages = 0;
  double medianUs = 0.0;
  double p99Us = 0.0;
};

[[nodiscard]] std::expected<LoopbackLatency, std::string> loopbackLatency(std::size_t bytes,
                                                                          std::size_t messages);

}  // namespace vem::bench
