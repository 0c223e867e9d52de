// The plate camera's model (calib/core/plate_camera.h): distortion and undistortion invert each
// other, a pixel's world direction projects back to the pixel, a point behind the camera has no
// pixel, and the level look-at keeps +Y up the image.
#include "calib/core/plate_camera.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "plate_truth.h"

namespace vem::calib {
namespace {

using testing::plateTruth;

class PlateCameraModel : public ::testing::TestWithParam<PlateLensModel> {};

TEST_P(PlateCameraModel, UndistortingADistortedPixelGivesItBack) {
  const PlateCamera truth = plateTruth(GetParam());
  for (double y = 0.0; y <= 539.0; y += 53.9) {
    for (double x = 0.0; x <= 959.0; x += 95.9) {
      const glm::dvec2 ideal(x, y);
      const glm::dvec2 distorted = distortedFromIdealPx(truth.intrinsics, ideal);
      const glm::dvec2 back = idealFromDistortedPx(truth.intrinsics, distorted);
      EXPECT_NEAR(back.x, x, 1e-6) << "at (" << x << ", " << y << ")";
      EXPECT_NEAR(back.y, y, 1e-6) << "at (" << x << ", " << y << ")";
    }
  }
}

TEST_P(PlateCameraModel, APixelsWorldDirectionProjectsBackToThePixel) {
  const PlateCamera truth = plateTruth(GetParam());
  for (double y = 0.0; y <= 539.0; y += 67.0) {
    for (double x = 0.0; x <= 959.0; x += 119.0) {
      const glm::dvec3 dir = worldDirectionFromPlate(truth.intrinsics, *truth.pose, {x, y});
      EXPECT_NEAR(glm::length(dir), 1.0, 1e-12);
      const auto pixel = plateFromWorldDirection(truth.intrinsics, *truth.pose, dir);
      ASSERT_TRUE(pixel.has_value());
      EXPECT_NEAR(pixel->x, x, 1e-6);
      EXPECT_NEAR(pixel->y, y, 1e-6);
      // A point 3 m along the ray lands on the same pixel.
      const auto point =
          plateFromWorld(truth.intrinsics, *truth.pose, truth.pose->positionWorldM + 3.0 * dir);
      ASSERT_TRUE(point.has_value());
      EXPECT_NEAR(point->x, x, 1e-6);
      EXPECT_NEAR(point->y, y, 1e-6);
    }
  }
}

TEST_P(PlateCameraModel, APointBehindTheCameraHasNoPixel) {
  const PlateCamera truth = plateTruth(GetParam());
  const glm::dvec3 forward = glm::transpose(truth.pose->cameraFromWorld)[2];
  EXPECT_FALSE(plateFromWorld(truth.intrinsics, *truth.pose, truth.pose->positionWorldM - forward));
  EXPECT_TRUE(plateFromWorld(truth.intrinsics, *truth.pose, truth.pose->positionWorldM + forward));
}

TEST_P(PlateCameraModel, ThePrincipalPointLooksDownTheOpticalAxis) {
  const PlateCamera truth = plateTruth(GetParam());
  const glm::dvec3 dir =
      cameraDirectionFromPlate(truth.intrinsics, {truth.intrinsics.cxPx, truth.intrinsics.cyPx});
  EXPECT_NEAR(dir.z, 1.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(BothLenses, PlateCameraModel,
                         ::testing::Values(PlateLensModel::BrownConrady,
                                           PlateLensModel::KannalaBrandt));

TEST(PlateCamera, LookingAtKeepsTheWorldsUpUpTheImage) {
  const PlatePose pose = plateLookingAt({0.0, 1.5, -2.0}, {0.0, 0.0, 0.0});
  // Right-handed rotation.
  EXPECT_NEAR(glm::determinant(pose.cameraFromWorld), 1.0, 1e-12);
  // World +Y appears with camera -Y (up the image) and no sideways part.
  const glm::dvec3 upCamera = pose.cameraFromWorld * glm::dvec3(0.0, 1.0, 0.0);
  EXPECT_LT(upCamera.y, 0.0);
  EXPECT_NEAR(upCamera.x, 0.0, 1e-12);
  // The target is straight ahead.
  const glm::dvec3 target = cameraFromWorldM(pose, {0.0, 0.0, 0.0});
  EXPECT_NEAR(target.x, 0.0, 1e-12);
  EXPECT_NEAR(target.y, 0.0, 1e-12);
  EXPECT_GT(target.z, 0.0);
}

TEST(PlateCamera, TheFloorBoardsAxesAreTheWorldsConvention) {
  const glm::dmat3 w = worldFromBoard();
  EXPECT_EQ(w * glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0));   // world X = board X
  EXPECT_EQ(w * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1));   // world Z = board Y
  EXPECT_EQ(w * glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));  // world Y = -board Z
  EXPECT_NEAR(glm::determinant(w), 1.0, 0.0);
}

}  // namespace
}  // namespace vem::calib
