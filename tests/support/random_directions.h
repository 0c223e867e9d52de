// Uniformly distributed random unit vectors for the tests (seeded, so every run is the same).
#pragma once

#include <cmath>
#include <numbers>
#include <random>

#include <glm/vec3.hpp>

namespace vem::testing {

inline glm::dvec3 randomUnitVector(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double y = 1.0 - 2.0 * unit(rng);
  const double phi = 2.0 * std::numbers::pi * unit(rng);
  const double ring = std::sqrt(1.0 - y * y);
  return {ring * std::cos(phi), y, ring * std::sin(phi)};
}

}  // namespace vem::testing
