// The generic fisheye lens model of Kannala and Brandt (2006), used for the geometric calibration of
// paper 004 section 5.1: the radial distance on the sensor is an odd polynomial of the angle from
// the optical axis,
//     r(theta) = k1 theta + k2 theta^3 + k3 theta^5 + k4 theta^7 + k5 theta^9   (pixels),
// with the principal point (cx, cy) and an aspect ratio between the rows' and columns' scales.
// It is OpenCV's fisheye model written in pixels: k1 = fx, k(i+1) = fx * cv_k(i), aspect = fy / fx.
//
// Conventions:
// - Camera frame: +Z is the optical axis (out of the lens), +X along increasing sensor columns u,
//   +Y along increasing sensor rows v (down the image). Right-handed.
// - Sensor coordinates as raw_frame.h (pixel centres at integers).
// - u = cx + r(theta) cos(psi), v = cy + aspect r(theta) sin(psi), where psi = atan2(y, x) of the
//   camera-frame direction and theta = atan2(hypot(x, y), z) in [0, pi]: fields of view beyond 180
//   degrees (theta up to 100 degrees and more) are handled.
// - A lens is usable up to maxThetaRad (half its field of view), where r must be increasing.
#pragma once

#include <array>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vem::calib {

struct KannalaBrandtLens {
  std::array<double, 5> kPx{};  // k1 .. k5, pixels per radian^(2i-1)
  glm::dvec2 principalPointPx{0.0, 0.0};
  double aspect = 1.0;                  // row scale / column scale
  double maxThetaRad = 1.6580627893946132;  // 95 degrees: a 190-degree lens

  // r(theta) in pixels, and its derivative.
  [[nodiscard]] double radiusPx(double thetaRad) const;
  [[nodiscard]] double radiusDerivativePx(double thetaRad) const;
  // theta with r(theta) = radiusPx, by safeguarded Newton; nullopt beyond r(maxThetaRad).
  [[nodiscard]] std::optional<double> thetaFromRadius(double radiusPx) const;

  // Sensor position of a camera-frame direction (any length > 0); nullopt beyond maxThetaRad.
  [[nodiscard]] std::optional<glm::dvec2> sensorFromCamera(const glm::dvec3& dirCamera) const;
  // Unit camera-frame direction of a sensor position; nullopt outside the lens circle.
  [[nodiscard]] std::optional<glm::dvec3> cameraFromSensor(const glm::dvec2& sensorPx) const;
};

// Why a lens cannot be used: r not increasing up to maxThetaRad, non-finite or non-positive k1,
// or aspect not positive. nullopt when the lens is fine.
[[nodiscard]] std::optional<const char*> lensDefect(const KannalaBrandtLens& lens);

// An equidistant lens (r = f theta) whose image circle of `circleRadiusPx` spans `fovDeg`, centred
// on a sensor of width x height: a starting point for fits and the simulator's default.
[[nodiscard]] KannalaBrandtLens equidistantLens(int width, int height, double fovDeg,
                                                double circleRadiusPx);

}  // namespace vem::calib
