// Finding the checkerboard (board_detection.h): the corners' order, frames of every format, empty
// frames, and the refinement on the board plane. Each test is named after the bug it catches.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "calib/core/board_detection.h"
#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "fisheye_truth.h"

namespace vem::calib {
namespace {

// The board turned by `spinDeg` about the optical axis, its centre on the axis `distanceMm` away.
BoardPose spunPose(const Checkerboard& board, double spinDeg, double distanceMm) {
  BoardPose pose;
  pose.cameraFromBoard =
      glm::mat3_cast(glm::angleAxis(testing::radians(spinDeg), glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 centreMm(0.5 * (board.innerCols - 1) * board.squareMm,
                            0.5 * (board.innerRows - 1) * board.squareMm, 0.0);
  pose.boardOriginCameraMm = glm::dvec3(0.0, 0.0, distanceMm) - pose.cameraFromBoard * centreMm;
  return pose;
}

std::vector<glm::dvec2> trueCorners(const KannalaBrandtLens& lens, const BoardPose& pose,
                                    const Checkerboard& board) {
  std::vector<glm::dvec2> corners;
  for (const glm::dvec3& c : boardCornersMm(board))
    corners.push_back(*lens.sensorFromCamera(cameraFromBoardMm(pose, c)));
  return corners;
}

double maxDistancePx(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, glm::length(a[i] - b[i]));
  return worst;
}

double rmsDistancePx(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += glm::dot(a[i] - b[i], a[i] - b[i]);
  return std::sqrt(sum / double(a.size()));
}

RawFrame boardFrame(const CameraCalibration& truth, const Checkerboard& board,
                    const BoardPose& pose, std::uint64_t seed) {
  SimulationOptions options;
  options.noise.readNoiseCode = testing::kTruthReadNoiseCode;
  options.noise.seed = seed;
  return simulateBoardView(board, pose, truth, options, testing::kBoardWhiteCdM2,
                           testing::kBoardBlackCdM2);
}

TEST(BoardDetection, CornersOutOfOrderWhenOpenCvStartsFromAnotherEnd) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  for (double spinDeg : {0.0, 90.0, 160.0, 180.0, 270.0}) {
    const BoardPose pose = spunPose(board, spinDeg, 800.0);
    const auto found = detectCheckerboard(boardFrame(truth, board, pose, 3), board);
    ASSERT_TRUE(found.has_value()) << "spin " << spinDeg;
    EXPECT_LT(maxDistancePx(*found, trueCorners(*truth.lens, pose, board)), 1.0)
        << "spin " << spinDeg << ": corner k must be the board's corner k";
  }
}

TEST(BoardDetection, SymmetricBoardMirroredWhenRowsAreReversedAlone) {
  // 8 x 6 corners: turned by 180 degrees the board looks the same, so either end may come
  // first; but the order must stay a rigid turn of the board's, never a mirror image.
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board{8, 6, 60.0};
  for (double spinDeg : {0.0, 180.0}) {
    const BoardPose pose = spunPose(board, spinDeg, 800.0);
    const auto found = detectCheckerboard(boardFrame(truth, board, pose, 4), board);
    ASSERT_TRUE(found.has_value()) << "spin " << spinDeg;
    const std::vector<glm::dvec2> expected = trueCorners(*truth.lens, pose, board);
    std::vector<glm::dvec2> turned(expected.rbegin(), expected.rend());
    EXPECT_LT(std::min(maxDistancePx(*found, expected), maxDistancePx(*found, turned)), 1.0)
        << "spin " << spinDeg;
  }
}

TEST(BoardDetection, BoardSeenFromBehindOrderedWronglyWhenHandednessOrColourIsIgnored) {
  // The frame flipped left to right: the board as seen through from behind. Its corners must
  // still come in an order whose rows and columns turn like the image's +u and +v (the printed
  // side's handedness): the truth's rows taken bottom up (not its columns right to left, which
  // would put a white square first).
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = spunPose(board, 25.0, 800.0);
  RawFrame frame = boardFrame(truth, board, pose, 9);
  for (int v = 0; v < frame.height; ++v) {
    std::reverse(frame.codes.begin() + std::ptrdiff_t(v) * frame.width,
                 frame.codes.begin() + std::ptrdiff_t(v + 1) * frame.width);
  }
  const std::vector<glm::dvec2> corners = trueCorners(*truth.lens, pose, board);
  std::vector<glm::dvec2> expected;
  for (int row = board.innerRows - 1; row >= 0; --row) {
    for (int col = 0; col < board.innerCols; ++col) {
      const glm::dvec2 p = corners[std::size_t(row * board.innerCols + col)];
      expected.emplace_back(frame.width - 1 - p.x, p.y);
    }
  }
  const auto found = detectCheckerboard(frame, board);
  ASSERT_TRUE(found.has_value());
  EXPECT_LT(maxDistancePx(*found, expected), 1.0);
}

TEST(BoardDetection, LogFrameMissedWhenGreyLevelsAreNotSpreadByPercentiles) {
  CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  // The board spans about 480 of the frame's 30000 codes (the rest: black outside the image
  // circle): 4 grey levels if the codes were scaled linearly to 8 bits.
  truth.photometric->response = LogResponse{{30000.0, 30000.0, 30000.0}, {150.0, 150.0, 150.0}};
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = spunPose(board, 20.0, 900.0);
  SimulationOptions options;
  options.noise.readNoiseCode = 3.0;
  const RawFrame frame = simulateBoardView(board, pose, truth, options, testing::kBoardWhiteCdM2,
                                           testing::kBoardBlackCdM2);
  const auto found = detectCheckerboard(frame, board);
  ASSERT_TRUE(found.has_value());
  EXPECT_LT(maxDistancePx(*found, trueCorners(*truth.lens, pose, board)), 1.0);
}

TEST(BoardDetection, ColourFrameMissedWhenChannelsAreNotCombined) {
  CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  truth.camera.pixelFormat = {3, 12};
  truth.photometric->response = LogResponse{{1500.0, 1560.0, 1620.0}, {200.0, 210.0, 220.0}};
  truth.photometric->blackLevelCode = 64.0;
  truth.photometric->saturationCode = 4095.0;
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = spunPose(board, -35.0, 900.0);
  const auto found = detectCheckerboard(boardFrame(truth, board, pose, 5), board);
  ASSERT_TRUE(found.has_value());
  EXPECT_LT(maxDistancePx(*found, trueCorners(*truth.lens, pose, board)), 1.0);
}

// The outermost view the pose generator makes for the 190-degree lens: squeezed and bent.
struct RimView {
  CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  Checkerboard board = testing::testBoard();
  BoardPose pose;
  RawFrame frame;
  std::vector<glm::dvec2> detected;
  std::vector<glm::dvec2> truthCorners;
};

const RimView& rimView() {
  static const RimView view = [] {
    RimView v;
    v.pose = boardPosesCoveringLens(v.board, *v.truth.lens, 800, 800, 12, 7).back();
    v.frame = boardFrame(v.truth, v.board, v.pose, 8);
    v.detected = detectCheckerboard(v.frame, v.board).value_or(std::vector<glm::dvec2>{});
    v.truthCorners = trueCorners(*v.truth.lens, v.pose, v.board);
    return v;
  }();
  return view;
}

TEST(BoardDetection, RimCornersBiasedWhenNotRemeasuredOnTheBoardPlane) {
  const RimView& v = rimView();
  ASSERT_EQ(v.detected.size(), v.truthCorners.size());
  const std::vector<glm::dvec2> refined =
      refineCorners(v.frame, v.board, *v.truth.lens, v.pose, v.detected);
  const double detectedRms = rmsDistancePx(v.detected, v.truthCorners);
  const double refinedRms = rmsDistancePx(refined, v.truthCorners);
  std::printf("rim view: detected corners %.3f px RMS from the truth, refined %.3f px\n",
              detectedRms, refinedRms);
  EXPECT_LT(refinedRms, 0.15);
  EXPECT_LT(refinedRms, 0.5 * detectedRms);
}

TEST(BoardDetection, RefinedCornersEchoTheModelWhenTheyShouldReadTheImage) {
  const RimView& v = rimView();
  ASSERT_EQ(v.detected.size(), v.truthCorners.size());
  // A lens 1 % too long and a board 3 mm off: their corners miss by 3 pixels or more.
  KannalaBrandtLens lens = *v.truth.lens;
  for (double& k : lens.kPx) k *= 1.01;
  BoardPose pose = v.pose;
  pose.boardOriginCameraMm += glm::dvec3(3.0, -2.0, 1.0);
  const std::vector<glm::dvec2> modelled = trueCorners(lens, pose, v.board);
  ASSERT_GT(rmsDistancePx(modelled, v.truthCorners), 3.0);
  const std::vector<glm::dvec2> refined = refineCorners(v.frame, v.board, lens, pose, v.detected);
  EXPECT_LT(rmsDistancePx(refined, v.truthCorners), 0.15);
}

}  // namespace
}  // namespace vem::calib
