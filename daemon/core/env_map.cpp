#include "core/env_map.h"

#include <cmath>
#include <numbers>

#include "util/contract.h"

namespace vem {

const char* layoutName(MapLayout layout) {
  return layout == MapLayout::Sphere ? "sphere" : "hemisphere";
}

EnvMap EnvMap::filled(MapLayout layout, int width, int height, glm::vec3 value) {
  EnvMap map{layout, width, height, {}};
  map.rgb.resize(map.pixelCount() * 3);
  for (std::size_t i = 0; i < map.pixelCount(); ++i) {
    map.rgb[3 * i + 0] = value.x;
    map.rgb[3 * i + 1] = value.y;
    map.rgb[3 * i + 2] = value.z;
  }
  return map;
}

glm::vec3 EnvMap::at(int x, int y) const {
  VEM_EXPECTS(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void EnvMap::set(int x, int y, glm::vec3 value) {
  VEM_EXPECTS(x >= 0 && x < width && y >= 0 && y < height);
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  rgb[i] = value.x;
  rgb[i + 1] = value.y;
  rgb[i + 2] = value.z;
}

double thetaMaxRad(MapLayout layout) {
  return layout == MapLayout::Sphere ? std::numbers::pi : std::numbers::pi / 2;
}

double coveredSolidAngleSr(MapLayout layout) {
  return layout == MapLayout::Sphere ? 4 * std::numbers::pi : 2 * std::numbers::pi;
}

glm::dvec3 directionFromAngles(double thetaRad, double phiRad) {
  const double sinTheta = std::sin(thetaRad);
  return {sinTheta * std::cos(phiRad), std::cos(thetaRad), sinTheta * std::sin(phiRad)};
}

double phiFromColumnCoord(MapLayout layout, int width, double xc) {
  const double psi = 2 * std::numbers::pi * xc / width;
  return layout == MapLayout::Sphere ? psi - std::numbers::pi : psi;
}

double thetaFromRowCoord(MapLayout layout, int height, double yc) {
  return thetaMaxRad(layout) * yc / height;
}

glm::dvec3 pixelCentreDirection(const EnvMap& map, int x, int y) {
  return directionFromAngles(thetaFromRowCoord(map.layout, map.height, y + 0.5),
                             phiFromColumnCoord(map.layout, map.width, x + 0.5));
}

double pixelSolidAngleSr(MapLayout layout, int width, int height, int y) {
  const double top = thetaFromRowCoord(layout, height, y);
  const double bottom = thetaFromRowCoord(layout, height, y + 1);
  // cos a - cos b = 2 sin((a + b) / 2) sin((b - a) / 2): exact also for thin rows at the poles.
  const double band = 2 * std::sin(0.5 * (top + bottom)) * std::sin(0.5 * (bottom - top));
  return 2 * std::numbers::pi / width * band;
}

}  // namespace vem
