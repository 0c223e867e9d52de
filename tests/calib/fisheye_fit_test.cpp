// The geometric calibration (fisheye_fit.h): exact recovery from exact corners beyond 90 degrees,
// the acceptance criterion from simulated views of 190- and 200-degree lenses (RMS under
// 0.5 px, every direction of the image circle within 0.2 degrees of the truth's), and every
// refusal. The fit always starts from its own guess, never from the truth. Each test is named
// after the bug it catches.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "calib/core/fisheye_fit.h"
#include "fisheye_truth.h"

namespace vem::calib {
namespace {

using testing::degrees;
using testing::radians;

constexpr int kViews = 12;
constexpr std::uint64_t kPoseSeed = 7;

// The truth's corners for every view, plus Gaussian noise of `noisePx` (no image: the fit alone).
std::vector<std::vector<glm::dvec2>> projectedCorners(const KannalaBrandtLens& lens,
                                                      const std::vector<BoardPose>& poses,
                                                      double noisePx, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> noise(0.0, noisePx);
  std::vector<std::vector<glm::dvec2>> views;
  for (const BoardPose& pose : poses) {
    std::vector<glm::dvec2>& corners = views.emplace_back();
    for (const glm::dvec3& c : boardCornersMm(testing::testBoard())) {
      const glm::dvec2 p = *lens.sensorFromCamera(cameraFromBoardMm(pose, c));
      corners.push_back(noisePx > 0.0 ? p + glm::dvec2(noise(engine), noise(engine)) : p);
    }
  }
  return views;
}

std::vector<BoardPose> posesFor(const KannalaBrandtLens& lens) {
  return boardPosesCoveringLens(testing::testBoard(), lens, testing::kTruthSensorPx,
                                testing::kTruthSensorPx, kViews, kPoseSeed);
}

FisheyeFitOptions optionsFor(double fovDeg) {
  FisheyeFitOptions options;
  options.fovDeg = fovDeg;
  return options;
}

struct DirectionError {
  double worstDeg = 0.0;
  double atThetaDeg = 0.0;
};

// Over the truth's whole image circle (theta 0 to maxTheta every 0.25 degrees, every 5 degrees of
// azimuth): the angle between the truth's direction and the one the fitted lens gives the same
// sensor point. The fitted lens may end its circle a hair inside the truth's, so it is evaluated
// with maxTheta 1 degree larger (its polynomial, not its limit, is under test).
DirectionError directionError(const KannalaBrandtLens& truth, const KannalaBrandtLens& fitted) {
  KannalaBrandtLens evaluated = fitted;
  evaluated.maxThetaRad += radians(1.0);
  DirectionError e;
  const int steps = int(std::round(4.0 * degrees(truth.maxThetaRad)));
  for (int i = 0; i <= steps; ++i) {
    const double theta = truth.maxThetaRad * i / steps;
    for (int j = 0; j < 72; ++j) {
      const glm::dvec3 dir = testing::cameraDirection(theta, radians(5.0 * j));
      const std::optional<glm::dvec3> back =
          evaluated.cameraFromSensor(*truth.sensorFromCamera(dir));
      const double error = back ? testing::angleBetweenDeg(dir, *back) : 180.0;
      if (error > e.worstDeg) e = {error, degrees(theta)};
    }
  }
  return e;
}

TEST(FisheyeFit, FitFailsBeyondNinetyDegreesWhenThetaUsesAtan) {
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(200.0);
  const auto poses = posesFor(truth);
  const auto corners = projectedCorners(truth, poses, 0.0, 1);
  int beyondNinety = 0;
  for (const BoardPose& pose : poses)
    for (const glm::dvec3& c : boardCornersMm(testing::testBoard()))
      beyondNinety += cameraFromBoardMm(pose, c).z < 0.0 ? 1 : 0;
  ASSERT_GT(beyondNinety, 50) << "the views must reach behind the lens's plane";
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, optionsFor(200.0));
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_LT(fit->quality.rmsReprojectionPx, 1e-6);
  EXPECT_LT(directionError(truth, fit->lens).worstDeg, 1e-5);
  EXPECT_NEAR(fit->lens.aspect, truth.aspect, 1e-8);
  EXPECT_NEAR(fit->lens.principalPointPx.x, truth.principalPointPx.x, 1e-5);
  EXPECT_NEAR(fit->lens.principalPointPx.y, truth.principalPointPx.y, 1e-5);
  EXPECT_NEAR(fit->lens.maxThetaRad, radians(100.0), 1e-12);
  EXPECT_EQ(fit->quality.views, kViews);
  EXPECT_EQ(fit->quality.corners, kViews * 54);
}

// The acceptance test: simulated frames in, lens out, compared with the truth.
void expectAcceptedLens(double fovDeg) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(fovDeg);
  const Checkerboard board = testing::testBoard();
  const auto poses = posesFor(*truth.lens);
  std::vector<RawFrame> frames;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    SimulationOptions options;
    options.noise.readNoiseCode = testing::kTruthReadNoiseCode;
    options.noise.seed = 40 + i;
    frames.push_back(simulateBoardView(board, poses[i], truth, options, testing::kBoardWhiteCdM2,
                                       testing::kBoardBlackCdM2));
  }
  const auto fit = calibrateFisheye(frames, board, optionsFor(fovDeg));
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  const DirectionError e = directionError(*truth.lens, fit->lens);
  const double worstView = *std::max_element(fit->viewRmsPx.begin(), fit->viewRmsPx.end());
  std::printf(
      "%g-degree lens: RMS %.3f px (worst view %.3f px), directions within %.3f deg "
      "(worst at theta %.1f deg)\n",
      fovDeg, fit->quality.rmsReprojectionPx, worstView, e.worstDeg, e.atThetaDeg);
  EXPECT_LT(fit->quality.rmsReprojectionPx, 0.5);
  EXPECT_LT(e.worstDeg, 0.2);
  EXPECT_FALSE(lensDefect(fit->lens).has_value());
}

TEST(FisheyeFit, Lens190DriftsWhenCornersAreNotRemeasuredOnTheBoardPlane) {
  expectAcceptedLens(190.0);
}

TEST(FisheyeFit, Lens200FailsWhenPosesStartInTheOpticalAxisFrame) { expectAcceptedLens(200.0); }

TEST(FisheyeFit, TooFewViewsAcceptedWhenMinViewsIsIgnored) {
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(190.0);
  auto corners = projectedCorners(truth, posesFor(truth), 0.1, 2);
  corners.resize(3);
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, optionsFor(190.0));
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::TooFewViews);
  EXPECT_NE(fit.error().message.find("3 views"), std::string::npos) << fit.error().message;
  EXPECT_NE(fit.error().message.find("at least 4"), std::string::npos) << fit.error().message;
}

TEST(FisheyeFit, IncompleteViewAcceptedWhenCornerCountIsNotChecked) {
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(190.0);
  auto corners = projectedCorners(truth, posesFor(truth), 0.1, 3);
  corners[5].pop_back();
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, optionsFor(190.0));
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::BoardNotFound);
  EXPECT_EQ(fit.error().view, 5);
}

TEST(FisheyeFit, BlankFrameAcceptedWhenAMissingBoardIsNotRefused) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  std::vector<RawFrame> frames;
  SimulationOptions options;
  frames.push_back(simulateBoardView(board, posesFor(*truth.lens).front(), truth, options,
                                     testing::kBoardWhiteCdM2, testing::kBoardBlackCdM2));
  frames.push_back(RawFrame::blank(800, 800, {1, 16}));
  const auto fit = calibrateFisheye(frames, board, optionsFor(190.0));
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::BoardNotFound);
  EXPECT_EQ(fit.error().view, 1);
  EXPECT_NE(fit.error().message.find("view 1"), std::string::npos) << fit.error().message;
}

TEST(FisheyeFit, PoorFitAcceptedWhenTheRmsLimitIsIgnored) {
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(190.0);
  const auto corners = projectedCorners(truth, posesFor(truth), 0.3, 4);
  FisheyeFitOptions options = optionsFor(190.0);
  EXPECT_TRUE(fitFisheye(corners, testing::testBoard(), 800, 800, options).has_value());
  options.maxRmsPx = 0.05;
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, options);
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::ErrorTooHigh);
  EXPECT_GE(fit.error().view, 0);
  EXPECT_NE(fit.error().message.find("0.05 px"), std::string::npos) << fit.error().message;
}

TEST(FisheyeFit, BadViewHiddenWhenOnlyTheOverallRmsIsChecked) {
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(190.0);
  auto corners = projectedCorners(truth, posesFor(truth), 0.05, 5);
  std::mt19937_64 engine(9);
  std::normal_distribution<double> mislocated(0.0, 1.5);
  for (glm::dvec2& c : corners[7]) c += glm::dvec2(mislocated(engine), mislocated(engine));
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, optionsFor(190.0));
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::ErrorTooHigh);
  EXPECT_EQ(fit.error().view, 7);
  EXPECT_NE(fit.error().message.find("view 7"), std::string::npos) << fit.error().message;
}

TEST(FisheyeFit, FoldingLensAcceptedWhenTheDefectIsNotChecked) {
  // Views of a 190-degree lens, claimed to be 300 degrees wide: the polynomial, fitted up to about
  // 90 degrees, turns back long before 150.
  const KannalaBrandtLens truth = testing::fisheyeTruthLens(190.0);
  const auto corners = projectedCorners(truth, posesFor(truth), 0.05, 6);
  const auto fit = fitFisheye(corners, testing::testBoard(), 800, 800, optionsFor(300.0));
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, FisheyeRefusal::LensFolds) << fit.error().message;
}

}  // namespace
}  // namespace vem::calib
