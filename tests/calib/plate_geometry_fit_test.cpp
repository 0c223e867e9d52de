// The plate camera's geometric calibration on simulated views (calib/core/plate_board_simulation.h,
// plate_intrinsics_fit.h, plate_pose_fit.h): the corners the detector finds give intrinsics within
// stated tolerances of the truth at an RMS under 0.5 px, and the floor board gives the camera's
// pose to millimetres and a tenth of a degree, above the floor even when the corners come mirrored.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "calib/core/board_detection.h"
#include "calib/core/plate_board_simulation.h"
#include "calib/core/plate_intrinsics_fit.h"
#include "calib/core/plate_pose_fit.h"
#include "plate_truth.h"

namespace vem::calib {
namespace {

using testing::kFloorBoard;
using testing::kPlateBoard;
using testing::plateTruth;

constexpr double kWhiteCode = 0.7 * 255.0;
constexpr double kBlackCode = kWhiteCode / 16.0;

SimulationOptions simulation(std::uint64_t seed) {
  SimulationOptions options;
  options.noise.readNoiseCode = 1.0;
  options.noise.seed = seed;
  return options;
}

std::vector<std::vector<glm::dvec2>> detectedViews(const PlateCamera& truth, int count) {
  std::vector<std::vector<glm::dvec2>> views;
  const std::vector<BoardPose> poses = plateBoardPoses(kPlateBoard, truth.intrinsics, count, 7);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const RawFrame frame = simulatePlateBoardView(kPlateBoard, poses[i], truth, simulation(i + 1),
                                                  kWhiteCode, kBlackCode);
    auto corners = detectCheckerboard(frame, kPlateBoard);
    EXPECT_TRUE(corners.has_value()) << "view " << i;
    if (corners) views.push_back(std::move(*corners));
  }
  return views;
}

// The angle of the rotation between two rotations, degrees.
double rotationErrorDeg(const glm::dmat3& a, const glm::dmat3& b) {
  const glm::dmat3 d = a * glm::transpose(b);
  const double cosAngle = std::clamp((d[0][0] + d[1][1] + d[2][2] - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(cosAngle) * 180.0 / std::numbers::pi;
}

class PlateGeometryFit : public ::testing::TestWithParam<PlateLensModel> {};

TEST_P(PlateGeometryFit, SimulatedBoardsGiveTheTruthsIntrinsicsUnderHalfAPixel) {
  const PlateCamera truth = plateTruth(GetParam());
  const auto views = detectedViews(truth, 12);
  ASSERT_EQ(views.size(), 12u);
  const auto fit = fitPlateIntrinsics(views, kPlateBoard, 960, 540, {GetParam(), 3, 1.0});
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_LT(fit->quality.rmsReprojectionPx, 0.5);
  EXPECT_EQ(fit->quality.views, 12);
  EXPECT_EQ(fit->quality.corners, 12 * 54);
  const PlateIntrinsics& got = fit->intrinsics;
  const PlateIntrinsics& want = truth.intrinsics;
  // Focal lengths within 0.5 %, the principal point within 3 px.
  EXPECT_NEAR(got.fxPx, want.fxPx, 0.005 * want.fxPx);
  EXPECT_NEAR(got.fyPx, want.fyPx, 0.005 * want.fyPx);
  EXPECT_NEAR(got.cxPx, want.cxPx, 3.0);
  EXPECT_NEAR(got.cyPx, want.cyPx, 3.0);
  // What matters: a view the fit has not seen (the floor board, corners exact) is reprojected
  // through the fitted intrinsics and the pose fitted with them to under 0.5 px.
  std::vector<glm::dvec2> floor;
  for (const glm::dvec3& boardMm : boardCornersMm(kFloorBoard))
    floor.push_back(
        *plateFromCamera(want, cameraFromBoardMm(floorBoardPose(*truth.pose), boardMm)));
  const auto pose = fitPlatePose(floor, kFloorBoard, got, 0.5);
  ASSERT_TRUE(pose.has_value()) << pose.error().message;
  EXPECT_LT(glm::length(pose->pose.positionWorldM - truth.pose->positionWorldM), 0.02);
}

TEST_P(PlateGeometryFit, TheFloorBoardGivesTheTruthsPose) {
  const PlateCamera truth = plateTruth(GetParam());
  const RawFrame frame = simulatePlateBoardView(kFloorBoard, floorBoardPose(*truth.pose), truth,
                                                simulation(99), kWhiteCode, kBlackCode);
  const auto corners = detectCheckerboard(frame, kFloorBoard);
  ASSERT_TRUE(corners.has_value());
  const auto fit = fitPlatePose(*corners, kFloorBoard, truth.intrinsics, 1.0);
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_FALSE(fit->boardTurned);
  EXPECT_LT(fit->quality.rmsReprojectionPx, 0.5);
  EXPECT_LT(glm::length(fit->pose.positionWorldM - truth.pose->positionWorldM), 0.005);
  EXPECT_LT(rotationErrorDeg(fit->pose.cameraFromWorld, truth.pose->cameraFromWorld), 0.1);
}

INSTANTIATE_TEST_SUITE_P(BothLenses, PlateGeometryFit,
                         ::testing::Values(PlateLensModel::BrownConrady,
                                           PlateLensModel::KannalaBrandt));

TEST(PlatePoseFit, MirroredCornerOrderStillPutsTheCameraAboveTheFloor) {
  const PlateCamera truth = plateTruth();
  std::vector<glm::dvec2> corners;
  for (const glm::dvec3& boardMm : boardCornersMm(kFloorBoard))
    corners.push_back(
        *plateFromWorld(truth.intrinsics, *truth.pose, worldFromBoard() * boardMm / 1000.0));
  // The rows in reverse order: the board's Y, and with it its Z, reversed.
  std::vector<glm::dvec2> mirrored;
  for (int row = kFloorBoard.innerRows - 1; row >= 0; --row)
    for (int col = 0; col < kFloorBoard.innerCols; ++col)
      mirrored.push_back(corners[std::size_t(row * kFloorBoard.innerCols + col)]);
  const auto fit = fitPlatePose(mirrored, kFloorBoard, truth.intrinsics, 0.01);
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_TRUE(fit->boardTurned);
  EXPECT_GT(fit->pose.positionWorldM.y, 0.0);
  // The world is the truth's moved to the first listed corner, the last row's: same rotation and
  // height, Z shifted by the rows' span.
  const glm::dvec3 shift(0.0, 0.0, (kFloorBoard.innerRows - 1) * kFloorBoard.squareMm / 1000.0);
  EXPECT_LT(glm::length(fit->pose.positionWorldM - (truth.pose->positionWorldM - shift)), 1e-6);
  EXPECT_LT(rotationErrorDeg(fit->pose.cameraFromWorld, truth.pose->cameraFromWorld), 1e-6);
}

TEST(PlatePoseFit, CornersOfAnotherBoardAreRefused) {
  const PlateCamera truth = plateTruth();
  const std::vector<glm::dvec2> corners(10, glm::dvec2(100.0, 100.0));
  const auto fit = fitPlatePose(corners, kFloorBoard, truth.intrinsics, 1.0);
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, PlateFitRefusal::WrongCornerCount);
}

TEST(PlateIntrinsicsFit, TooFewViewsAreRefused) {
  const std::vector<std::vector<glm::dvec2>> views(2);
  const auto fit = fitPlateIntrinsics(views, kPlateBoard, 960, 540, {});
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, PlateFitRefusal::TooFewViews);
}

}  // namespace
}  // namespace vem::calib
