// Cube-map lookup: the O(1) map from a direction to a texel of a cube map, and from a texel back to
// its centre direction. The angular regions (angular_regions.h) store one region index per texel,
// so a normal finds its region with a single table read, on the CPU as in a GL cube-map texture.
//
// Conventions:
// - Directions are in the world frame of env_map.h (right-handed, +Y up); they must be non-zero and
//   need not be unit. Returned directions are unit.
// - Six faces in OpenGL order +X, -X, +Y, -Y, +Z, -Z (index 0..5), each F x F texels. The face
//   coordinates follow the OpenGL 4.6 specification, section 8.13 "Cube Map Texture Selection", so
//   the table uploads to a GL cube map as is:
//       face   ma   sc   tc          s = (sc / |ma| + 1) / 2,   t = (tc / |ma| + 1) / 2
//        +X    +x   -z   -y          column = floor(s F), row = floor(t F), both clamped to F - 1
//        -X    -x   +z   -y
//        +Y    +y   +x   +z
//        -Y    -y   +x   -z
//        +Z    +z   +x   -y
//        -Z    -z   -x   -y
//   The major axis ma is the component of largest magnitude; ties (on cube edges only) go to x,
//   then y, then z.
// - Texel index = (face F + row) F + column, in [0, 6 F^2).
// - Angles in radians.
//
// Paper 004 section 4.1 ("a LUT discretizing the sphere on faces of a cube") and section 5.2.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>

namespace vem {

inline constexpr int kCubeFaceCount = 6;

enum class CubeFace : std::uint8_t { PosX, NegX, PosY, NegY, PosZ, NegZ };

// A point on a face: s, t in [0, 1].
struct CubeFaceCoord {
  CubeFace face = CubeFace::PosX;
  double s = 0.5;
  double t = 0.5;
};

struct CubeTexel {
  CubeFace face = CubeFace::PosX;
  int column = 0;  // along s, in [0, F)
  int row = 0;     // along t, in [0, F)
  bool operator==(const CubeTexel&) const = default;
};

[[nodiscard]] CubeFaceCoord cubeFaceCoordOf(glm::dvec3 dir);
// Inverse of cubeFaceCoordOf for unit directions: the unit direction through (face, s, t).
[[nodiscard]] glm::dvec3 directionFromCubeFaceCoord(const CubeFaceCoord& coord);

[[nodiscard]] CubeTexel cubeTexelOf(glm::dvec3 dir, int faceSize);
[[nodiscard]] glm::dvec3 cubeTexelCentreDirection(const CubeTexel& texel, int faceSize);
// Largest angle between the texel's centre direction and any direction inside the texel (reached at
// a corner: the texel is a convex spherical quadrilateral well inside a hemisphere).
[[nodiscard]] double cubeTexelRadiusRad(const CubeTexel& texel, int faceSize);

[[nodiscard]] std::size_t cubeTexelCount(int faceSize);
[[nodiscard]] std::size_t cubeTexelIndex(const CubeTexel& texel, int faceSize);
[[nodiscard]] CubeTexel cubeTexelFromIndex(std::size_t index, int faceSize);

}  // namespace vem
