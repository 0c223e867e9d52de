// The texels of one cube-map level as samples of the sphere: each texel's centre direction, its
// solid angle and its radiance times that solid angle. What the prefilters integrate over
// (environment_lighting.h) and what the soft shadows' strata are made of (soft_shadows.h).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "core/cube_map.h"

namespace vem::render {

struct TexelSample {
  glm::vec3 dir{0.0F, 1.0F, 0.0F};  // unit, world frame
  glm::vec3 radianceSr{0.0F};       // radiance times solidAngleSr; black where not finite
  float solidAngleSr = 0.0F;        // (2/F)^2 max|d|^3: the face's area element seen from the centre
};

// Texel (face, row, column) of `level` is entry (face F + row) F + column.
[[nodiscard]] std::vector<TexelSample> texelSamplesOf(const CubeMapLevel& level);

// The unit direction through the point (column + u, row + v) of the texel at `index` of a level of
// facePx texels a side (the indexing above), u and v in [0, 1]: a point drawn inside the texel.
[[nodiscard]] glm::vec3 directionInCubeTexel(std::size_t index, int facePx, float u, float v);

// The first level whose face is at most facePx (the smallest level when every face is larger).
[[nodiscard]] const CubeMapLevel& cubeLevelAtMost(const CubeMap& cube, int facePx);

}  // namespace vem::render
