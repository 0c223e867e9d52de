// The Kannala-Brandt lens (kannala_brandt.h) and the camera's orientation (camera_orientation.h):
// round trips, closed forms and the documented conventions. Each test is named after the bug it
// catches.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "calib/core/camera_orientation.h"
#include "calib/core/kannala_brandt.h"
#include "fisheye_truth.h"

namespace vem::calib {
namespace {

using testing::cameraDirection;
using testing::radians;

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(KannalaBrandt, RoundTripBreaksBeyondNinetyDegreesWhenThetaUsesAtan) {
  const KannalaBrandtLens lens = testing::fisheyeTruthLens(200.0);
  double worstRad = 0.0;
  for (int i = 0; i <= 400; ++i) {
    // Up to 100 degrees, the lens's rim, less 1e-9 rad: on the rim itself rounding decides.
    const double theta = std::min(radians(100.0) * i / 400.0, lens.maxThetaRad - 1e-9);
    for (int j = 0; j < 36; ++j) {
      const glm::dvec3 dir = cameraDirection(theta, 2.0 * std::numbers::pi * j / 36.0);
      const std::optional<glm::dvec2> sensor = lens.sensorFromCamera(dir);
      ASSERT_TRUE(sensor.has_value()) << "theta " << testing::degrees(theta);
      const std::optional<glm::dvec3> back = lens.cameraFromSensor(*sensor);
      ASSERT_TRUE(back.has_value()) << "theta " << testing::degrees(theta);
      worstRad = std::max(worstRad, radians(testing::angleBetweenDeg(dir, *back)));
    }
  }
  EXPECT_LT(worstRad, 1e-9);
}

TEST(KannalaBrandt, ImageMisplacedWhenPolynomialOrAspectIsAppliedWrongly) {
  const KannalaBrandtLens lens = testing::fisheyeTruthLens(190.0);
  const double theta = radians(80.0);
  const double t2 = theta * theta;
  const double r = theta * (236.0 + t2 * (-9.0 + t2 * (2.5 + t2 * (-0.45 + t2 * 0.035))));
  EXPECT_NEAR(lens.radiusPx(theta), r, 1e-9);
  const double h = 1e-6;
  EXPECT_NEAR(lens.radiusDerivativePx(theta),
              (lens.radiusPx(theta + h) - lens.radiusPx(theta - h)) / (2.0 * h), 1e-5);
  // +X lands right of the principal point at r; +Y below it at aspect * r (rows scale).
  const glm::dvec2 c = lens.principalPointPx;
  const glm::dvec2 right = *lens.sensorFromCamera(cameraDirection(theta, 0.0));
  const glm::dvec2 down = *lens.sensorFromCamera(cameraDirection(theta, 0.5 * std::numbers::pi));
  EXPECT_NEAR(right.x - c.x, r, 1e-9);
  EXPECT_NEAR(right.y - c.y, 0.0, 1e-9);
  EXPECT_NEAR(down.x - c.x, 0.0, 1e-9);
  EXPECT_NEAR(down.y - c.y, 1.012 * r, 1e-9);
  EXPECT_EQ(*lens.sensorFromCamera({0.0, 0.0, 2.0}), c);  // the axis, any length
}

TEST(KannalaBrandt, DirectionsInventedWhenTheImageCircleIsNotEnforced) {
  const KannalaBrandtLens lens = testing::fisheyeTruthLens(190.0);
  const double rimPx = lens.radiusPx(lens.maxThetaRad);
  EXPECT_NEAR(*lens.thetaFromRadius(rimPx), lens.maxThetaRad, 1e-12);
  EXPECT_NEAR(*lens.thetaFromRadius(0.5 * rimPx), 0.5 * lens.maxThetaRad, 0.1);
  EXPECT_FALSE(lens.thetaFromRadius(rimPx + 0.01).has_value());
  EXPECT_FALSE(lens.thetaFromRadius(-1.0).has_value());
  EXPECT_FALSE(lens.cameraFromSensor(lens.principalPointPx + glm::dvec2(rimPx + 0.5, 0.0)));
  EXPECT_TRUE(lens.cameraFromSensor(lens.principalPointPx + glm::dvec2(rimPx - 0.5, 0.0)));
  // Rows scale by the aspect: the circle reaches further down than across.
  EXPECT_TRUE(lens.cameraFromSensor(lens.principalPointPx + glm::dvec2(0.0, rimPx + 2.0)));
  EXPECT_FALSE(lens.sensorFromCamera(cameraDirection(lens.maxThetaRad + 1e-6, 1.0)).has_value());
}

TEST(KannalaBrandt, LensDefectMissesAFoldBetweenTheEndsWhenOnlyTheEndsAreChecked) {
  KannalaBrandtLens lens;
  lens.maxThetaRad = 1.4;
  // r' = 100 - 240 t^2 + 125 t^4: positive at both ends, negative around t = 1.
  lens.kPx = {100.0, -80.0, 25.0, 0.0, 0.0};
  ASSERT_GT(lens.radiusDerivativePx(0.0), 0.0);
  ASSERT_GT(lens.radiusDerivativePx(lens.maxThetaRad), 0.0);
  ASSERT_GT(lens.radiusPx(lens.maxThetaRad), 0.0);
  EXPECT_TRUE(lensDefect(lens).has_value());
  EXPECT_FALSE(lensDefect(testing::fisheyeTruthLens(190.0)).has_value());
  EXPECT_FALSE(lensDefect(testing::fisheyeTruthLens(200.0)).has_value());
  KannalaBrandtLens flipped = testing::fisheyeTruthLens(190.0);
  flipped.kPx[0] = -flipped.kPx[0];
  EXPECT_TRUE(lensDefect(flipped).has_value());
  KannalaBrandtLens squashed = testing::fisheyeTruthLens(190.0);
  squashed.aspect = 0.0;
  EXPECT_TRUE(lensDefect(squashed).has_value());
}

TEST(KannalaBrandt, StartingLensMissesTheCircleWhenEquidistantScaleIsWrong) {
  const KannalaBrandtLens lens = equidistantLens(640, 512, 190.0, 250.0);
  EXPECT_NEAR(lens.radiusPx(lens.maxThetaRad), 250.0, 1e-9);
  EXPECT_NEAR(lens.maxThetaRad, radians(95.0), 1e-12);
  EXPECT_EQ(lens.principalPointPx, glm::dvec2(319.5, 255.5));
  EXPECT_FALSE(lensDefect(lens).has_value());
}

// Camera orientation: the reference pose and the three angles of camera_orientation.h.

TEST(CameraOrientation, SkyMirroredWhenImageUpIsNotPhiNinety) {
  const glm::dmat3 m = worldFromCamera({});
  expectNear(m * glm::dvec3(0.0, 0.0, 1.0), {0.0, 1.0, 0.0}, 1e-12);   // optical axis: zenith
  expectNear(m * glm::dvec3(1.0, 0.0, 0.0), {1.0, 0.0, 0.0}, 1e-12);   // +u: phi = 0
  expectNear(m * glm::dvec3(0.0, -1.0, 0.0), {0.0, 0.0, 1.0}, 1e-12);  // image up: phi = 90
}

TEST(CameraOrientation, ImageRotationTurnsTheWrongWayWhenItsSignIsFlipped) {
  for (double rotationDeg : {30.0, 90.0, -60.0}) {
    const glm::dmat3 worldFromCam = worldFromCamera({rotationDeg, 0.0, 0.0});
    // The world's phi = 0, 40 degrees down from the zenith, seen in the camera frame...
    const glm::dvec3 phiZero(std::sin(radians(40.0)), std::cos(radians(40.0)), 0.0);
    const glm::dvec3 cam = glm::transpose(worldFromCam) * phiZero;
    // ...lies rotationDeg counter-clockwise (on screen, v down) from +u.
    const double a = radians(rotationDeg);
    EXPECT_NEAR(cam.x, std::sin(radians(40.0)) * std::cos(a), 1e-12) << rotationDeg;
    EXPECT_NEAR(cam.y, -std::sin(radians(40.0)) * std::sin(a), 1e-12) << rotationDeg;
    EXPECT_NEAR(cam.z, std::cos(radians(40.0)), 1e-12) << rotationDeg;
  }
}

TEST(CameraOrientation, TiltTipsTowardTheWrongAzimuthWhenItsAxisIsWrong) {
  const glm::dvec3 axis(0.0, 0.0, 1.0);
  expectNear(worldFromCamera({0.0, 90.0, 0.0}) * axis, {1.0, 0.0, 0.0}, 1e-12);     // to phi 0
  expectNear(worldFromCamera({0.0, 90.0, 90.0}) * axis, {0.0, 0.0, 1.0}, 1e-12);    // to phi 90
  expectNear(worldFromCamera({0.0, 180.0, 30.0}) * axis, {0.0, -1.0, 0.0}, 1e-12);  // down
  const double t = radians(30.0), p = radians(135.0);
  expectNear(worldFromCamera({20.0, 30.0, 135.0}) * axis,
             {std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p)}, 1e-12);
}

TEST(CameraOrientation, WorldFromCameraIsNoRotationWhenComposedWrongly) {
  for (const CameraOrientation o :
       {CameraOrientation{17.0, 33.0, 250.0}, CameraOrientation{-120.0, 95.0, 10.0},
        CameraOrientation{200.0, 170.0, -45.0}}) {
    const glm::dmat3 m = worldFromCamera(o);
    const glm::dmat3 shouldBeIdentity = glm::transpose(m) * m;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(shouldBeIdentity[c][r], c == r ? 1.0 : 0.0, 1e-12);
    }
    EXPECT_NEAR(glm::determinant(m), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace vem::calib
