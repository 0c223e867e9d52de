// How the camera sits in the world: the rotation between the camera frame of kannala_brandt.h and
// the world frame of daemon/core/env_map.h (+Y up, phi = 0 toward +X, phi = 90 degrees toward +Z).
//
// The reference pose looks straight up: the optical axis +Z_camera is the zenith +Y_world, sensor
// +u (+X_camera) points to phi = 0 (+X_world), and sensor -v (up the image) to phi = 90 degrees
// (+Z_world); so, seen on screen, phi runs counter-clockwise from the image's right.
// From there, three angles in degrees, applied in this order:
// - imageRotationDeg: rotates the camera about its optical axis, so that phi = 0 lies at this angle
//   counter-clockwise from the image's +u direction ("where phi = 0 points");
// - tiltDeg: tips the optical axis away from the zenith by this angle (0 = up, 90 = horizontal,
//   180 = straight down),
// - tiltAzimuthDeg: toward this world azimuth phi.
#pragma once

#include <glm/mat3x3.hpp>

namespace vem::calib {

struct CameraOrientation {
  double imageRotationDeg = 0.0;
  double tiltDeg = 0.0;
  double tiltAzimuthDeg = 0.0;
};

// Rotation taking camera-frame vectors to world-frame vectors (orthonormal, det +1).
[[nodiscard]] glm::dmat3 worldFromCamera(const CameraOrientation& orientation);

}  // namespace vem::calib
