// The lights vemd publishes for a processed frame, the same for every sink that shows lights (the
// JSON-lines file, the preview image, the stream): the temporal filter's output when the
// frame has one, else the frame's own lights (while the filter fills, after a reset, or with the
// filter off). The recorder is different: it stores each frame's own lights with the frame, so a
// replay can check them (recorder_sink.h).
//
// `clustering`, when present, is taken to cluster exactly the published set (processed_frame.h:
// "of the filtered set, or the raw one without filter"); a clustering whose clusterOfLight does not
// have one valid entry per published light is ignored rather than misattributed.
#pragma once

#include <cstdint>

#include "core/light.h"
#include "core/light_clustering.h"
#include "frames/processed_frame.h"

namespace vem {

struct PublishedLights {
  const LightSet* lights = nullptr;        // never null
  bool filtered = false;                   // the temporal filter's output
  std::uint64_t lightsSeq = 0;             // the frame the lights stand for
  const Clustering* clustering = nullptr;  // of *lights, or null
};

// `frame.captured` must not be null.
[[nodiscard]] PublishedLights publishedLights(const ProcessedFrame& frame);

}  // namespace vem
