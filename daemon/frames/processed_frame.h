// ProcessedFrame: what vemd's pipeline makes of one CapturedFrame, handed to every sink.
//
// Conventions: the polar map is the calibrated environment (daemon/core/env_map.h, Hemisphere
// layout, cd/m^2); `lights` are the frame's own lights, `filtered` the temporal filter's output
// (absent while the filter fills or after a reset; its seq is the frame's minus the filter delay);
// `clustering` is present when clustering is on. Timings in microseconds per stage.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/env_map.h"
#include "core/light.h"
#include "core/light_clustering.h"
#include "frames/captured_frame.h"

namespace vem {

struct StageTiming {
  std::string stage;  // "calibrate", "tables", "lights", "filter", "cluster", ...
  double micros = 0.0;
};

struct ProcessedFrame {
  const CapturedFrame* captured = nullptr;  // borrowed for the sinks' call
  const EnvMap* polar = nullptr;            // borrowed
  LightSet lights;
  std::optional<LightSet> filtered;
  std::uint64_t filteredSeq = 0;         // the frame the filtered set stands for
  std::optional<Clustering> clustering;  // of the filtered set (or the raw one without filter)
  std::vector<StageTiming> timings;
};

}  // namespace vem
