// CapturedFrame: one raw frame as a source delivers it to vemd's pipeline, with its identity in
// time. Sources (replay, synthetic, cameras) all produce these.
//
// Conventions: seq increases by one per frame the source produced (gaps mean frames lost before
// vemd saw them); captureTsNs is the capture instant in nanoseconds on the source's clock (the
// recording's for replay, CLOCK_MONOTONIC for live sources); arrivalNs is when vemd received it
// (CLOCK_MONOTONIC), for the latency from arrival.
#pragma once

#include <cstdint>

#include "frames/raw_frame.h"

namespace vem {

struct CapturedFrame {
  RawFrame frame;
  std::uint64_t seq = 0;
  std::int64_t captureTsNs = 0;
  std::int64_t arrivalNs = 0;
};

}  // namespace vem
