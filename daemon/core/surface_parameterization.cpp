#include "core/surface_parameterization.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/concentric_map.h"

namespace vem {
namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
double oneMinusCosMax(MapLayout layout) { return layout == MapLayout::Sphere ? 2.0 : 1.0; }
}  // namespace

CylinderPoint cylinderFromSquare(MapLayout layout, glm::dvec2 square) {
  if (layout == MapLayout::Sphere) return cylinderFromSquareOctahedral(square);
  const DiskPoint disk = diskFromSquare(square);
  return {disk.rho * disk.rho, disk.psi / kTwoPi};
}

glm::dvec2 squareFromCylinder(MapLayout layout, CylinderPoint point) {
  if (layout == MapLayout::Sphere) return squareFromCylinderOctahedral(point);
  return squareFromDisk({std::sqrt(std::clamp(point.s, 0.0, 1.0)), kTwoPi * point.w});
}

glm::dvec3 surfaceDirection(MapLayout layout, CylinderPoint point) {
  const double oneMinusCos = oneMinusCosMax(layout) * std::clamp(point.s, 0.0, 1.0);
  const double cosTheta = 1 - oneMinusCos;
  const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2 - oneMinusCos)));
  const double azimuth = kTwoPi * point.w;
  return {sinTheta * std::cos(azimuth), cosTheta, sinTheta * std::sin(azimuth)};
}

CylinderPoint cylinderFromSurfaceDirection(MapLayout layout, glm::dvec3 dir) {
  const double theta = std::atan2(std::hypot(dir.x, dir.z), dir.y);
  const double half = std::sin(0.5 * theta);
  double azimuth = std::atan2(dir.z, dir.x);
  if (azimuth < 0) azimuth += kTwoPi;
  double w = azimuth / kTwoPi;
  if (w >= 1) w -= 1;
  return {std::clamp(2 * half * half / oneMinusCosMax(layout), 0.0, 1.0), w};
}

}  // namespace vem
