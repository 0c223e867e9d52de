// The bounds a reader checks every length and size against before it allocates, so a damaged or
// hostile file can never make it allocate more than a few frames' worth of memory.
#pragma once

#include <cstdint>

namespace vem::recording {

struct ReadLimits {
  // Largest frame, uncompressed (width x height x channels x 2 bytes): 128 MiB, e.g. 8192 x 8192
  // monochrome 16-bit. A header announcing larger frames is refused.
  std::uint64_t maxFrameBytes = std::uint64_t(128) << 20;
  // Largest header record payload (identity and calibration text): 16 MiB.
  std::uint32_t maxHeaderBytes = std::uint32_t(16) << 20;
  // Largest frame metadata message (FrameMeta with its lights): 16 MiB.
  std::uint32_t maxFrameMetaBytes = std::uint32_t(16) << 20;
  // Largest index record payload: 1 GiB, about 50 million frames.
  std::uint32_t maxIndexBytes = std::uint32_t(1) << 30;
};

// Largest frame sides the format accepts, in pixels (further bounded by maxFrameBytes).
inline constexpr std::uint32_t kMaxFrameSidePx = 65535;

}  // namespace vem::recording
