#include "client/render/texel_samples.h"

#include <algorithm>
#include <cmath>

namespace vem::render {

std::vector<TexelSample> texelSamplesOf(const CubeMapLevel& level) {
  const int f = level.facePx;
  std::vector<TexelSample> out;
  out.reserve(std::size_t(6 * f * f));
  const float cellArea = (2.0F / float(f)) * (2.0F / float(f));
  for (int face = 0; face < 6; ++face) {
    const std::vector<float>& texels = level.faces[std::size_t(face)];
    for (int row = 0; row < f; ++row) {
      for (int column = 0; column < f; ++column) {
        const glm::vec3 d = cubeTexelDirection(face, f, column + 0.5, row + 0.5);
        const float m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        const float sr = cellArea * m * m * m;
        const std::size_t i = 3 * (std::size_t(row) * std::size_t(f) + std::size_t(column));
        glm::vec3 radiance(texels[i], texels[i + 1], texels[i + 2]);
        if (!std::isfinite(radiance.x) || !std::isfinite(radiance.y) ||
            !std::isfinite(radiance.z)) {
          radiance = glm::vec3(0.0F);
        }
        out.push_back(TexelSample{d, radiance * sr, sr});
      }
    }
  }
  return out;
}

glm::vec3 directionInCubeTexel(std::size_t index, int facePx, float u, float v) {
  const std::size_t perFace = std::size_t(facePx) * std::size_t(facePx);
  const int face = int(index / perFace);
  const int row = int((index % perFace) / std::size_t(facePx));
  const int column = int(index % std::size_t(facePx));
  return cubeTexelDirection(face, facePx, double(column) + double(u), double(row) + double(v));
}

const CubeMapLevel& cubeLevelAtMost(const CubeMap& cube, int facePx) {
  for (const CubeMapLevel& level : cube.levels) {
    if (level.facePx <= facePx) return level;
  }
  return cube.levels.back();
}

}  // namespace vem::render
