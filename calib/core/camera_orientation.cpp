#include "calib/core/camera_orientation.h"

#include <cmath>
#include <numbers>

#include <glm/mat3x3.hpp>

namespace vem::calib {
namespace {

double radians(double deg) { return deg * std::numbers::pi / 180.0; }

// Rotation by `angle` about the unit `axis` (Rodrigues), as a column-major glm matrix.
glm::dmat3 rotationAbout(const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const double t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  // glm::dmat3(col0, col1, col2).
  return glm::dmat3(glm::dvec3(t * x * x + c, t * x * y + s * z, t * x * z - s * y),
                    glm::dvec3(t * x * y - s * z, t * y * y + c, t * y * z + s * x),
                    glm::dvec3(t * x * z + s * y, t * y * z - s * x, t * z * z + c));
}

}  // namespace

glm::dmat3 worldFromCamera(const CameraOrientation& orientation) {
  // Reference pose: camera +X -> world +X, camera +Y (down the image) -> world -Z, camera +Z -> +Y.
  const glm::dmat3 reference(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, -1.0),
                             glm::dvec3(0.0, 1.0, 0.0));
  // Rotating the camera about its axis by +a (counter-clockwise as seen on screen, i.e. from +u
  // toward -v) moves phi = 0 to angle a in the image: a rotation of the world about -Y_camera...
  // expressed in world terms, the camera turns about +Y_world by +a (phi = 0 then sits at image
  // angle a). phi runs counter-clockwise on screen, and a world rotation by +a about +Y takes
  // azimuth phi to phi - a (dir(phi) = (cos, ., sin)), hence the sign.
  const glm::dmat3 spin = rotationAbout(glm::dvec3(0.0, 1.0, 0.0), radians(orientation.imageRotationDeg));
  // Tilt: the optical axis (+Y_world in the reference) tips by tiltDeg toward azimuth tiltAzimuth,
  // a rotation about the horizontal axis perpendicular to that azimuth.
  const double phiT = radians(orientation.tiltAzimuthDeg);
  const glm::dvec3 toward(std::cos(phiT), 0.0, std::sin(phiT));
  const glm::dvec3 axis = glm::cross(glm::dvec3(0.0, 1.0, 0.0), toward);  // up x toward
  const glm::dmat3 tilt = rotationAbout(axis, radians(orientation.tiltDeg));
  return tilt * spin * reference;
}

}  // namespace vem::calib
