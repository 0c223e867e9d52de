// The stream benchmark's measurements, each against the real vemd (VemdProcess, a synthetic sky
// on 127.0.0.1 port 0) and real clients on loopback:
// - networkLatency: publish_unix_ns (processing done) to receivedUnixNs (a StreamClient holding
//   the decoded frame), both CLOCK_REALTIME, in ms;
// - messageSizes: bytes of each serialized ServerMessage a raw client receives: light frames per
//   light count, environment frames (cube maps) per face size and mip levels;
// - rateWithClients: vemd's processed frame rate at --rate max or a paced rate (its Status) with
//   N clients connected: one StreamClient that reads the Status plus N - 1 raw clients that read
//   and discard every message, each on its own thread; and vemd's CPU time per processed frame
//   (/proc/PID/stat), which shows what each client costs when the two cores are shared.
// Each returns one sentence when vemd or a client does not come up.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <string>
#include <vector>

namespace vem::bench {

struct LatencyResult {
  std::size_t frames = 0;
  double rateHz = 0.0;  // vemd's --rate
  double medianMs = 0.0;
  double p99Ms = 0.0;
  double maxMs = 0.0;
  std::uint64_t skipped = 0;  // seq gaps the client saw
};

[[nodiscard]] std::expected<LatencyResult, std::string> networkLatency(const std::string& vemdPath,
                                                                       std::size_t frames,
                                                                       double rateHz);

struct MessageSize {
  std::string what;            // "light frame, 64 lights", "cube map 64 px, 1 level"...
  double bytes = 0.0;          // median over the messages read
  double rawTexelBytes = 0.0;  // cube maps: texels before zstd; 0 for light frames
};

[[nodiscard]] std::expected<std::vector<MessageSize>, std::string> messageSizes(
    const std::string& vemdPath);

struct RateResult {
  std::string rate;  // vemd's --rate: "max" or frames per second
  std::size_t clients = 0;
  double processedHz = 0.0;    // median of vemd's Status.frame_rate_hz over the window
  double receivedHz = 0.0;     // light frames the StreamClient received per second
  std::uint64_t skipped = 0;   // seq gaps that client saw over the window
  std::uint64_t dropped = 0;   // frames vemd's capture queue dropped over the window
  double cpuMsPerFrame = 0.0;  // vemd's CPU time (all its threads, user + system) per frame
};

[[nodiscard]] std::expected<RateResult, std::string> rateWithClients(const std::string& vemdPath,
                                                                     const std::string& rate,
                                                                     std::size_t clients,
                                                                     double windowS);

// Issue 16, item 1: clients asking for cube maps, with or without the token, while vemd records.
struct CubemapLoad {
  std::size_t clients = 10;
  int facePx = 512;
  int levels = 8;
  double rateHz = 60.0;
  bool token = true;  // with the token (no budget), or read-only (within [stream]'s budget)
};

struct CubemapLoadResult {
  CubemapLoad load;
  double processedHz = 0.0;         // vemd's frames processed per second of the window
  std::uint64_t dropped = 0;        // frames vemd's capture queue dropped in the window
  std::uint64_t droppedInRun = 0;   // ... over the whole run (its final statistics)
  std::uint64_t recorded = 0;       // frames in the recording made meanwhile (whole run)
  std::uint64_t recordingGaps = 0;  // seq steps other than +1 in it
  double cubemapsPerS = 0.0;        // environment frames all the clients received per second
  std::uint64_t refused = 0;        // subscriptions the daemon refused
  double cpuMsPerFrame = 0.0;       // vemd's CPU time (all threads) per processed frame
};

// vemd at `rateHz` with --record, the load's clients subscribed and draining every message, for
// `windowS` after they are all connected.
[[nodiscard]] std::expected<CubemapLoadResult, std::string> rateWithCubemapLoad(
    const std::string& vemdPath, double rateHz, const CubemapLoad& load, double windowS);

}  // namespace vem::bench
