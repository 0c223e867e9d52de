// Truth cameras for the geometric calibration's tests (checkerboard, board detection, fisheye fit):
// a 16-bit log sensor of 800 x 800 pixels behind a 190- or a 200-degree Kannala-Brandt lens with
// every coefficient in use, the principal point off centre and an aspect of 1.012; and the board
// the tests photograph. Small sensors keep the tests fast; the lenses fill them.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "calib/core/camera_calibration.h"
#include "calib/core/checkerboard.h"

namespace vem::testing {

inline constexpr int kTruthSensorPx = 800;
inline constexpr double kBoardWhiteCdM2 = 500.0;
inline constexpr double kBoardBlackCdM2 = 20.0;
// Read noise: 60 codes against about 9700 codes between the board's black and white.
inline constexpr double kTruthReadNoiseCode = 60.0;

inline calib::Checkerboard testBoard() { return {9, 6, 60.0}; }

// k in pixels: r(95 deg) = 369 px (190 degrees), r(100 deg) = 356 px (200 degrees).
inline calib::KannalaBrandtLens fisheyeTruthLens(double fovDeg) {
  calib::KannalaBrandtLens lens;
  lens.kPx = fovDeg < 195.0 ? std::array{236.0, -9.0, 2.5, -0.45, 0.035}
                            : std::array{214.0, -6.0, 1.6, -0.30, 0.022};
  lens.maxThetaRad = 0.5 * fovDeg * std::numbers::pi / 180.0;
  lens.principalPointPx = {0.5 * (kTruthSensorPx - 1) + 7.3, 0.5 * (kTruthSensorPx - 1) - 5.8};
  lens.aspect = 1.012;
  return lens;
}

// code = 8000 + 3000 ln(L / 1 cd/m2), black level 1000, saturation 65000, Mono16.
inline calib::CameraCalibration fisheyeTruthCamera(double fovDeg) {
  calib::CameraCalibration camera;
  camera.camera = {"simulated fisheye", "TRUTH-FISHEYE", kTruthSensorPx, kTruthSensorPx, {1, 16}};
  calib::PhotometricCalibration photometric;
  photometric.response = calib::LogResponse{{8000.0, 8000.0, 8000.0}, {3000.0, 3000.0, 3000.0}};
  photometric.blackLevelCode = 1000.0;
  photometric.saturationCode = 65000.0;
  camera.photometric = photometric;
  camera.lens = fisheyeTruthLens(fovDeg);
  return camera;
}

inline double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }
inline double radians(double deg) { return deg * std::numbers::pi / 180.0; }

// The angle between two directions, degrees (accurate for small angles, unlike acos).
inline double angleBetweenDeg(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return degrees(std::atan2(std::hypot(c.x, c.y, c.z), a.x * b.x + a.y * b.y + a.z * b.z));
}

// A camera-frame direction at polar angle theta from the optical axis and azimuth psi.
inline glm::dvec3 cameraDirection(double thetaRad, double psiRad) {
  return {std::sin(thetaRad) * std::cos(psiRad), std::sin(thetaRad) * std::sin(psiRad),
          std::cos(thetaRad)};
}

}  // namespace vem::testing
