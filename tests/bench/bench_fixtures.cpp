#include "bench_fixtures.h"

#include <fmt/format.h>

#include "mapio/map_file.h"
#include "support/test_maps.h"

namespace vem::bench {

std::string StageConfig::label() const {
  return fmt::format("{}x{}, {} lights", width, height, lights);
}

const std::vector<StageConfig>& stageConfigs() {
  static const std::vector<StageConfig> configs{
      {360, 90, 300}, {1024, 256, 1024}, {2048, 512, 1024}};
  return configs;
}

const std::vector<NamedMap>& sharedHdris() {
  static const std::vector<NamedMap> maps = [] {
    std::vector<NamedMap> loaded;
    for (const auto& path : testing::sharedHdriPaths()) {
      auto map = mapio::loadMap(path);
      if (map) loaded.push_back({path.stem().string(), std::move(*map)});
    }
    return loaded;
  }();
  return maps;
}

}  // namespace vem::bench
