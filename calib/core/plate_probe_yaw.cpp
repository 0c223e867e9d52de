#include "calib/core/plate_probe_yaw.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/env_map.h"
#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr double kMinHorizontalSin = 0.017452406437283512;  // sin(1 degree)

double wrapRad(double angle) {
  angle = std::remainder(angle, 2.0 * std::numbers::pi);
  return angle <= -std::numbers::pi ? angle + 2.0 * std::numbers::pi : angle;
}

}  // namespace

glm::dmat3 plateWorldFromProbeWorld(double yawRad) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), yawRad, glm::dvec3(0.0, 1.0, 0.0)));
}

glm::dvec3 directionFromAzimuthElevation(double azimuthRad, double elevationRad) {
  return directionFromAngles(std::numbers::pi / 2.0 - elevationRad, azimuthRad);
}

double azimuthRad(const glm::dvec3& dir) { return std::atan2(dir.z, dir.x); }

double elevationRad(const glm::dvec3& dir) {
  VEM_EXPECTS(glm::length(dir) > 0.0);
  return std::asin(std::clamp(dir.y / glm::length(dir), -1.0, 1.0));
}

std::optional<double> probeYawFromMarker(const glm::dvec3& markerPlateWorld,
                                         const glm::dvec3& markerProbeWorld) {
  for (const glm::dvec3& d : {markerPlateWorld, markerProbeWorld})
    if (std::hypot(d.x, d.z) < kMinHorizontalSin * glm::length(d)) return std::nullopt;
  return wrapRad(azimuthRad(markerProbeWorld) - azimuthRad(markerPlateWorld));
}

double markerParallaxRad(double baselineM, double distanceM) {
  VEM_EXPECTS(baselineM >= 0.0 && distanceM > 0.0);
  return baselineM >= distanceM ? std::numbers::pi / 2.0 : std::asin(baselineM / distanceM);
}

}  // namespace vem::calib
