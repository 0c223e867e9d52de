// Well-spread point sets on the unit sphere (world frame of env_map.h: +Y up).
// The spherical Fibonacci lattice (golden-angle spiral, equal-area bands in y): used for the 64
// accuracy normals, for angular-region centres and wherever "uniformly over the sphere" is needed.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

namespace vem {

// n >= 1 unit vectors; point i has y = 1 - (2 i + 1) / n and azimuth i * golden angle.
[[nodiscard]] std::vector<glm::dvec3> fibonacciSphere(int n);

}  // namespace vem
