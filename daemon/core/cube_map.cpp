#include "core/cube_map.h"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>

#include "core/cube_map_lookup.h"
#include "core/sampling_tables.h"
#include "util/contract.h"

namespace vem {
namespace {

// Bilinear weights and the two neighbouring indices of a continuous pixel coordinate.
struct Taps {
  int lo;
  int hi;
  float weightHi;
};

Taps wrappedTaps(double coord, int size) {
  const double f = coord - 0.5;
  const double lo = std::floor(f);
  int i = int(lo) % size;
  if (i < 0) i += size;
  return {i, i + 1 == size ? 0 : i + 1, float(f - lo)};
}

Taps clampedTaps(double coord, int size) {
  const double f = coord - 0.5;
  const double lo = std::floor(f);
  const int i = int(lo);
  if (i < 0) return {0, 0, 0.0F};
  if (i >= size - 1) return {size - 1, size - 1, 0.0F};
  return {i, i + 1, float(f - lo)};
}

// Sanitised as the lights and the reference read the map (a channel that is NaN, infinite or
// negative makes the pixel black): sky.exr's 11 negative pixels beside its sun (down to -3394)
// took 12 % of the map's light out of its cube maps, so the cube and the lights disagreed.
glm::vec3 pixel(const EnvMap& map, int x, int y) { return glm::vec3(sanitizedRgb(map, x, y)); }

void fillLevel0(const EnvMap& map, CubeMapLevel& level) {
  const int size = level.facePx;
  for (int face = 0; face < kCubeFaceCount; ++face) {
    std::vector<float>& texels = level.faces[std::size_t(face)];
    texels.resize(std::size_t(size) * std::size_t(size) * 3);
    for (int row = 0; row < size; ++row) {
      for (int column = 0; column < size; ++column) {
        const glm::dvec3 dir =
            directionFromCubeFaceCoord({CubeFace(face), (column + 0.5) / size, (row + 0.5) / size});
        const glm::vec3 value = sampleEnvMapBilinear(map, dir);
        const std::size_t i = 3 * (std::size_t(row) * std::size_t(size) + std::size_t(column));
        texels[i] = value.x;
        texels[i + 1] = value.y;
        texels[i + 2] = value.z;
      }
    }
  }
}

CubeMapLevel boxHalved(const CubeMapLevel& above) {
  CubeMapLevel level;
  level.facePx = above.facePx / 2;
  const std::size_t size = std::size_t(level.facePx);
  const std::size_t stride = 3 * std::size_t(above.facePx);
  for (std::size_t face = 0; face < level.faces.size(); ++face) {
    const std::vector<float>& in = above.faces[face];
    std::vector<float>& out = level.faces[face];
    out.resize(size * size * 3);
    for (std::size_t row = 0; row < size; ++row) {
      const float* top = in.data() + 2 * row * stride;
      const float* bottom = top + stride;
      for (std::size_t column = 0; column < size; ++column) {
        for (std::size_t c = 0; c < 3; ++c) {
          const std::size_t left = 6 * column + c;
          out[3 * (row * size + column) + c] =
              0.25F * (top[left] + top[left + 3] + bottom[left] + bottom[left + 3]);
        }
      }
    }
  }
  return level;
}

}  // namespace

glm::vec3 cubeTexelDirection(int face, int facePx, double u, double v) {
  VEM_EXPECTS(face >= 0 && face < kCubeFaceCount && facePx >= 1);
  const double size = facePx;
  return glm::vec3(directionFromCubeFaceCoord({CubeFace(face), u / size, v / size}));
}

glm::vec3 sampleEnvMapBilinear(const EnvMap& map, glm::dvec3 dir) {
  VEM_EXPECTS(map.width > 0 && map.height > 0 && map.rgb.size() == map.pixelCount() * 3);
  if (map.layout == MapLayout::Hemisphere && dir.y < 0.0) return glm::vec3(0.0F);
  const double horizontal = std::hypot(dir.x, dir.z);
  const double thetaRad = std::atan2(horizontal, dir.y);
  double phiRad = std::atan2(dir.z, dir.x);  // (-pi, pi]
  // psi in [0, 2 pi) is the column parameter of both layouts (env_map.h).
  double psiRad = map.layout == MapLayout::Sphere ? phiRad + std::numbers::pi : phiRad;
  if (psiRad < 0.0) psiRad += 2 * std::numbers::pi;
  const double xc = map.width * psiRad / (2 * std::numbers::pi);
  const double yc = map.height * thetaRad / thetaMaxRad(map.layout);
  const Taps x = wrappedTaps(xc, map.width);
  const Taps y = clampedTaps(yc, map.height);
  const glm::vec3 top =
      pixel(map, x.lo, y.lo) * (1.0F - x.weightHi) + pixel(map, x.hi, y.lo) * x.weightHi;
  const glm::vec3 bottom =
      pixel(map, x.lo, y.hi) * (1.0F - x.weightHi) + pixel(map, x.hi, y.hi) * x.weightHi;
  return top * (1.0F - y.weightHi) + bottom * y.weightHi;
}

CubeMap cubeMapFromEnvMap(const EnvMap& map, int facePx, int levels) {
  VEM_EXPECTS(facePx >= 1 && levels >= 1);
  CubeMapLevel base;
  base.facePx = facePx;
  fillLevel0(map, base);
  return cubeMapFromLevel0(std::move(base), levels);
}

CubeMap cubeMapFromLevel0(CubeMapLevel base, int levels) {
  VEM_EXPECTS(base.facePx >= 1 && levels >= 1);
  CubeMap cube;
  cube.levels.reserve(std::size_t(levels));
  cube.levels.push_back(std::move(base));
  while (int(cube.levels.size()) < levels && cube.levels.back().facePx % 2 == 0) {
    cube.levels.push_back(boxHalved(cube.levels.back()));
  }
  return cube;
}

}  // namespace vem
