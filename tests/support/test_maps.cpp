#include "support/test_maps.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace vem::testing {

EnvMap proceduralSky(MapLayout layout, int width, int height) {
  EnvMap map = EnvMap::filled(layout, width, height, glm::vec3(0));
  const glm::dvec3 sunDir = glm::normalize(glm::dvec3(0.4, 0.6, -0.3));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 d = pixelCentreDirection(map, x, y);
      const double sky = d.y > 0 ? 0.4 + 0.6 * d.y : 0.15;
      const double glow = 20.0 * std::pow(std::max(0.0, glm::dot(d, sunDir)), 32.0);
      map.set(x, y,
              glm::vec3(float(0.6 * sky + glow), float(0.8 * sky + 0.8 * glow),
                        float(1.0 * sky + 0.5 * glow)));
    }
  }
  return map;
}

EnvMap hotPixelMap(MapLayout layout, int width, int height, int x, int y, float hot,
                   float background) {
  EnvMap map = EnvMap::filled(layout, width, height, glm::vec3(background));
  map.set(x, y, glm::vec3(hot));
  return map;
}

EnvMap rotatedColumns(const EnvMap& map, int columns) {
  EnvMap out = map;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const int to = ((x + columns) % map.width + map.width) % map.width;
      out.set(to, y, map.at(x, y));
    }
  }
  return out;
}

std::vector<std::filesystem::path> sharedHdriPaths() {
  std::vector<std::filesystem::path> paths;
  const std::filesystem::path dir = std::filesystem::path(VEM_SHARED_DATA_DIR) / "hdri";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() == ".exr") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace vem::testing
