#include "client/render/cube_map_sampling.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "core/cube_map_lookup.h"

namespace vem::render {

glm::vec3 sampleCubeMap(const CubeMap& cube, glm::vec3 dir, int level) {
  const int l = std::clamp(level, 0, int(cube.levels.size()) - 1);
  const CubeMapLevel& lv = cube.levels[std::size_t(l)];
  const CubeFaceCoord coord = cubeFaceCoordOf(glm::dvec3(dir));
  const std::vector<float>& face = lv.faces[std::size_t(coord.face)];
  const int f = lv.facePx;
  // Texel centres at (i + 0.5) / F; clamp to the face (no blending across edges).
  const double u = std::clamp(coord.s * f - 0.5, 0.0, double(f - 1));
  const double v = std::clamp(coord.t * f - 0.5, 0.0, double(f - 1));
  const int u0 = int(std::floor(u));
  const int v0 = int(std::floor(v));
  const int u1 = std::min(u0 + 1, f - 1);
  const int v1 = std::min(v0 + 1, f - 1);
  const auto fu = float(u - u0);
  const auto fv = float(v - v0);
  const auto texel = [&](int column, int row) {
    const std::size_t i = 3 * (std::size_t(row) * std::size_t(f) + std::size_t(column));
    return glm::vec3(face[i], face[i + 1], face[i + 2]);
  };
  const glm::vec3 top = glm::mix(texel(u0, v0), texel(u1, v0), fu);
  const glm::vec3 bottom = glm::mix(texel(u0, v1), texel(u1, v1), fu);
  return glm::mix(top, bottom, fv);
}

glm::vec3 sampleCubeMapSeamless(const CubeMap& cube, glm::vec3 dir, int level) {
  const int l = std::clamp(level, 0, int(cube.levels.size()) - 1);
  const CubeMapLevel& lv = cube.levels[std::size_t(l)];
  const CubeFaceCoord coord = cubeFaceCoordOf(glm::dvec3(dir));
  const int f = lv.facePx;
  const double u = coord.s * f - 0.5;
  const double v = coord.t * f - 0.5;
  const int u0 = int(std::floor(u));
  const int v0 = int(std::floor(v));
  const auto fu = float(u - u0);
  const auto fv = float(v - v0);
  const auto texel = [&](int column, int row) {
    CubeTexel at{coord.face, column, row};
    if (column < 0 || column >= f || row < 0 || row >= f) {
      at = cubeTexelOf(directionFromCubeFaceCoord(
                           {coord.face, (column + 0.5) / double(f), (row + 0.5) / double(f)}),
                       f);
    }
    const std::vector<float>& face = lv.faces[std::size_t(at.face)];
    const std::size_t i = 3 * (std::size_t(at.row) * std::size_t(f) + std::size_t(at.column));
    return glm::vec3(face[i], face[i + 1], face[i + 2]);
  };
  const glm::vec3 top = glm::mix(texel(u0, v0), texel(u0 + 1, v0), fu);
  const glm::vec3 bottom = glm::mix(texel(u0, v0 + 1), texel(u0 + 1, v0 + 1), fu);
  return glm::mix(top, bottom, fv);
}

glm::vec3 sampleBackground(const CubeMap& cube, MapLayout coverage, glm::vec3 dir) {
  if (coverage == MapLayout::Hemisphere && dir.y < 0.0F) return glm::vec3(0.0F);
  return sampleCubeMap(cube, dir, 0);
}

}  // namespace vem::render
