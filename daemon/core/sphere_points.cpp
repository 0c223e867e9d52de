#include "core/sphere_points.h"

#include <cmath>
#include <numbers>

namespace vem {

std::vector<glm::dvec3> fibonacciSphere(int n) {
  const double goldenAngle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<glm::dvec3> points;
  points.reserve(std::size_t(n));
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - (2.0 * i + 1.0) / n;
    const double ring = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = goldenAngle * i;
    points.emplace_back(ring * std::cos(phi), y, ring * std::sin(phi));
  }
  return points;
}

}  // namespace vem
