// What the benchmarks run on: a polar sky map of a given size with its light pipeline state, and
// the shared HDRIs for the accuracy figures.
#pragma once

#include <string>
#include <vector>

#include "core/angular_regions.h"
#include "core/env_map.h"
#include "core/light.h"
#include "core/sampling_tables.h"

namespace vem::bench {

struct StageConfig {
  int width;
  int height;
  std::size_t lights;
  [[nodiscard]] std::string label() const;  // "360x90, 300 lights"
};

// The configurations the issue names: the paper's 360 x 90 map with 300 lights, and 1024 x 256 and
// 2048 x 512 with 1024 lights; camera-style polar (hemisphere) maps.
[[nodiscard]] const std::vector<StageConfig>& stageConfigs();

struct NamedMap {
  std::string name;
  EnvMap map;
};
// The shared HDRIs (512 x 256 equirectangular); empty when ../shared/data is absent.
[[nodiscard]] const std::vector<NamedMap>& sharedHdris();

}  // namespace vem::bench
