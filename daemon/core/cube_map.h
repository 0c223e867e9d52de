// CubeMap: an environment map resampled onto the six faces of a cube, with a box-filtered mip
// chain, as vemd streams it to render clients (EnvironmentFrame in proto/vem_stream.proto) and as
// they upload it to a GL cube-map texture unchanged.
//
// Conventions:
// - Directions in the world frame of env_map.h (right-handed, +Y up). Faces in OpenGL order
//   +X, -X, +Y, -Y, +Z, -Z (index 0..5) with the orientation of the OpenGL 4.6 specification,
//   section 8.13, exactly as cube_map_lookup.h states it: texel (column, row) of a face lies at
//   s = (column + 0.5) / F, t = (row + 0.5) / F; row 0 is the first row GL uploads.
// - Each face holds F x F texels, row-major, three floats (linear RGB in the map's units, cd/m^2
//   once calibrated) per texel: faces[f][3 (row F + column) + channel].
// - Pixels are read sanitised (sampling_tables.h's sanitizedRgb: black when a channel is NaN,
//   infinite or negative), as the lights and the reference read them.
// - Level 0 samples the map bilinearly at each texel's centre direction (across the phi seam; rows
//   clamped at the poles and at a hemisphere's horizon). A Hemisphere map (vemd's polar map) covers
//   only y >= 0: texels whose centre lies below the horizon (y < 0) are black.
// - Level k > 0 has F >> k texels a side, each the mean of the 2 x 2 texels of level k - 1 below it
//   (a box-prefiltered chain). The chain stops early at the first odd face size.
// Pure: no allocation beyond the result, no state; thread-safe.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "core/env_map.h"

namespace vem {

struct CubeMapLevel {
  int facePx = 0;
  std::array<std::vector<float>, 6> faces;  // facePx * facePx * 3 floats each
};

struct CubeMap {
  std::vector<CubeMapLevel> levels;  // level 0 first; at least one
};

// The unit direction through the point (u, v) of `face` (0..5) of a cube of facePx texels a side,
// in texel units: u along the columns, v along the rows, both in [0, facePx]; the centre of texel
// (column, row) is (column + 0.5, row + 0.5). The single source of the face convention for the
// streamed cube maps (it delegates to cube_map_lookup.h's directionFromCubeFaceCoord).
[[nodiscard]] glm::vec3 cubeTexelDirection(int face, int facePx, double u, double v);

// The map's value in direction `dir` (unit), sampled bilinearly as level 0 of a cube map does.
[[nodiscard]] glm::vec3 sampleEnvMapBilinear(const EnvMap& map, glm::dvec3 dir);

// The cube map of `map` (Sphere or Hemisphere layout, non-empty): facePx >= 1 texels a side and up
// to `levels` >= 1 levels (fewer when a face size turns odd first: 64 px gives at most 7).
[[nodiscard]] CubeMap cubeMapFromEnvMap(const EnvMap& map, int facePx, int levels);

// The cube map whose level 0 is `base` (facePx >= 1), with its box-filtered chain of up to
// `levels` >= 1 levels (the same rule as above).
[[nodiscard]] CubeMap cubeMapFromLevel0(CubeMapLevel base, int levels);

}  // namespace vem
