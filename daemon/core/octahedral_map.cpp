#include "core/octahedral_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vem {

CylinderPoint cylinderFromSquareOctahedral(glm::dvec2 square) {
  const double a = 2 * square.x - 1;
  const double b = 2 * square.y - 1;
  const double d = std::abs(a) + std::abs(b);
  const double r = 1 - std::abs(1 - d);  // 0 at both poles, 1 on the equator
  // Azimuth within the quadrant, in [0, pi/2]; at the poles any value is right.
  const double quadrantAngle =
      r > 0 ? std::numbers::pi / 4 * ((std::abs(b) - std::abs(a)) / r + 1) : 0.0;
  double azimuth = std::atan2(std::copysign(std::sin(quadrantAngle), b),
                              std::copysign(std::cos(quadrantAngle), a));
  if (azimuth < 0) azimuth += 2 * std::numbers::pi;
  double w = azimuth / (2 * std::numbers::pi);
  if (w >= 1) w -= 1;
  const double s = d <= 1 ? 0.5 * r * r : 1 - 0.5 * r * r;
  return {s, w};
}

glm::dvec2 squareFromCylinderOctahedral(CylinderPoint point) {
  const bool upper = point.s <= 0.5;
  const double r = std::sqrt(upper ? 2 * point.s : 2 * (1 - point.s));
  const double azimuth = 2 * std::numbers::pi * point.w;
  const double x = std::cos(azimuth);
  const double y = std::sin(azimuth);
  const double quadrantAngle = std::atan2(std::abs(y), std::abs(x));  // [0, pi/2]
  const double d = upper ? r : 2 - r;
  const double diff = r * (4 * quadrantAngle / std::numbers::pi - 1);  // |b| - |a|
  const double absA = std::clamp(0.5 * (d - diff), 0.0, 1.0);
  const double absB = std::clamp(0.5 * (d + diff), 0.0, 1.0);
  const double a = std::copysign(absA, x);
  const double b = std::copysign(absB, y);
  return {0.5 * (a + 1), 0.5 * (b + 1)};
}

}  // namespace vem
