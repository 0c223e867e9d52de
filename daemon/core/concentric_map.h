// The concentric map between the unit square and the unit disk (Shirley and Chiu 1997, paper 004
// reference [SC97]): continuous, bijective on the open square, low distortion, area-preserving up
// to the constant pi (uniform points in the square give uniform points in the disk).
//
// Square: (u, v) in [0, 1]^2. Disk: radius rho in [0, 1] and angle psi in [0, 2 pi), psi = 0 along
// the square's +u half-axis (u > 1/2, v = 1/2), increasing toward +v. The angle wraps on that
// half-axis: the only place where psi jumps from 2 pi to 0 while the disk point moves continuously.
#pragma once

#include <glm/vec2.hpp>

namespace vem {

struct DiskPoint {
  double rho = 0.0;  // radius in [0, 1]
  double psi = 0.0;  // angle in [0, 2 pi)
};

[[nodiscard]] DiskPoint diskFromSquare(glm::dvec2 square);
[[nodiscard]] glm::dvec2 squareFromDisk(DiskPoint disk);

}  // namespace vem
