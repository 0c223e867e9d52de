// The checkerboard (checkerboard.h): the frames the simulator draws of it and the poses that cover
// a lens. Each test is named after the bug it catches.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "fisheye_truth.h"

namespace vem::calib {
namespace {

using testing::degrees;

// Noise-free codes of the truth camera's log response for the test board's shades.
constexpr double kBlackCode = 8000.0 + 3000.0 * 2.995732273553991;  // ln 20
constexpr double kWhiteCode = 8000.0 + 3000.0 * 6.214608098422191;  // ln 500
constexpr double kGreyCode = 8000.0 + 3000.0 * 4.605170185988092;   // ln 100 = ln sqrt(20 * 500)

// The board upright, its centre on the optical axis `distanceMm` away.
BoardPose centredPose(const Checkerboard& board, double distanceMm) {
  BoardPose pose;
  pose.boardOriginCameraMm = {-0.5 * (board.innerCols - 1) * board.squareMm,
                              -0.5 * (board.innerRows - 1) * board.squareMm, distanceMm};
  return pose;
}

SimulationOptions noiseFree(int supersamples) {
  SimulationOptions options;
  options.supersamples = supersamples;
  return options;
}

// The code of the pixel that board point (x, y), in squares from the first corner, falls in.
double codeAt(const RawFrame& frame, const KannalaBrandtLens& lens, const BoardPose& pose,
              const Checkerboard& board, double x, double y) {
  const glm::dvec3 p = cameraFromBoardMm(pose, glm::dvec3(x, y, 0.0) * board.squareMm);
  const glm::dvec2 s = *lens.sensorFromCamera(p);
  return frame.at(int(std::lround(s.x)), int(std::lround(s.y)));
}

TEST(BoardSimulation, PatternMisplacedWhenPoseOrSquareColoursAreWrong) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = centredPose(board, 900.0);
  const RawFrame frame = simulateBoardView(board, pose, truth, noiseFree(2),
                                           testing::kBoardWhiteCdM2, testing::kBoardBlackCdM2);
  const KannalaBrandtLens& lens = *truth.lens;
  // The square between corners (0, 0) and (1, 1) is black, as is the board's top-left square.
  EXPECT_NEAR(codeAt(frame, lens, pose, board, 0.5, 0.5), kBlackCode, 1.0);
  EXPECT_NEAR(codeAt(frame, lens, pose, board, -0.5, -0.5), kBlackCode, 1.0);
  EXPECT_NEAR(codeAt(frame, lens, pose, board, 1.5, 0.5), kWhiteCode, 1.0);
  EXPECT_NEAR(codeAt(frame, lens, pose, board, 0.5, 1.5), kWhiteCode, 1.0);
  EXPECT_NEAR(codeAt(frame, lens, pose, board, 8.5, 5.5), kWhiteCode, 1.0);   // 8 + 5 odd
  EXPECT_NEAR(codeAt(frame, lens, pose, board, -1.5, 3.0), kWhiteCode, 1.0);  // the margin
  EXPECT_NEAR(codeAt(frame, lens, pose, board, 9.5, 6.5), kWhiteCode, 1.0);
  EXPECT_NEAR(codeAt(frame, lens, pose, board, -2.5, -2.5), kGreyCode, 1.0);  // background
  // Board +X runs along +u and +Y along +v in the identity pose.
  const glm::dvec2 first = *lens.sensorFromCamera(cameraFromBoardMm(pose, {0.0, 0.0, 0.0}));
  const glm::dvec2 along = *lens.sensorFromCamera(cameraFromBoardMm(pose, {60.0, 60.0, 0.0}));
  EXPECT_GT(along.x, first.x + 5.0);
  EXPECT_GT(along.y, first.y + 5.0);
  EXPECT_EQ(frame.at(0, 0), 1000) << "outside the image circle: the black level";
}

TEST(BoardSimulation, BackOfTheBoardPrintedWhenSidesAreNotTold) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  BoardPose pose = centredPose(board, 900.0);
  // Turned about the board's vertical centre line: the camera sees its back.
  pose.cameraFromBoard =
      glm::dmat3(glm::dvec3(-1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(0.0, 0.0, -1.0));
  pose.boardOriginCameraMm.x = -pose.boardOriginCameraMm.x;
  const RawFrame frame = simulateBoardView(board, pose, truth, noiseFree(2),
                                           testing::kBoardWhiteCdM2, testing::kBoardBlackCdM2);
  for (const auto& [x, y] : {std::pair{0.5, 0.5}, std::pair{1.5, 0.5}, std::pair{-1.5, -1.5}}) {
    EXPECT_NEAR(codeAt(frame, *truth.lens, pose, board, x, y), kGreyCode, 1.0) << x << ", " << y;
  }
}

// Pixels that read none of black, white and grey: the ones an edge runs through.
int mixedPixels(const RawFrame& frame) {
  int mixed = 0;
  for (std::uint16_t code : frame.codes) {
    const double c = code;
    if (c > 1000.0 && std::abs(c - kBlackCode) > 50.0 && std::abs(c - kWhiteCode) > 50.0 &&
        std::abs(c - kGreyCode) > 50.0)
      ++mixed;
  }
  return mixed;
}

TEST(BoardSimulation, EdgesJaggedWhenPixelsAreNotSupersampled) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = centredPose(board, 900.0);
  const auto frameWith = [&](int supersamples) {
    return simulateBoardView(board, pose, truth, noiseFree(supersamples), testing::kBoardWhiteCdM2,
                             testing::kBoardBlackCdM2);
  };
  EXPECT_GT(mixedPixels(frameWith(2)), 500) << "edge pixels average their area";
  // One sample per pixel shows only pure shades, except along the image circle's rim.
  EXPECT_LT(mixedPixels(frameWith(1)), 50);
}

TEST(BoardSimulation, FramesNotReproducibleWhenNoiseIgnoresTheSeed) {
  const CameraCalibration truth = testing::fisheyeTruthCamera(190.0);
  const Checkerboard board = testing::testBoard();
  const BoardPose pose = centredPose(board, 900.0);
  SimulationOptions options = noiseFree(1);
  options.noise.readNoiseCode = testing::kTruthReadNoiseCode;
  const auto frame = [&](std::uint64_t seed) {
    options.noise.seed = seed;
    return simulateBoardView(board, pose, truth, options, testing::kBoardWhiteCdM2,
                             testing::kBoardBlackCdM2)
        .codes;
  };
  EXPECT_EQ(frame(5), frame(5));
  EXPECT_NE(frame(5), frame(6));
}

// Every pose against the promises of boardPosesCoveringLens.
struct Coverage {
  double minCornerThetaDeg = 180.0;
  double maxCornerThetaDeg = 0.0;
  int viewsBeyondNinety = 0;
  int quadrantsAtRim =
      0;  // of the four image quadrants, how many hold a corner within 8 deg of the rim
};

Coverage checkPoses(const KannalaBrandtLens& lens, const std::vector<BoardPose>& poses,
                    const Checkerboard& board) {
  Coverage c;
  bool quadrant[4] = {false, false, false, false};
  for (const BoardPose& pose : poses) {
    bool beyondNinety = false;
    const glm::dvec3 frontNormal = -pose.cameraFromBoard[2];
    for (const glm::dvec3& cornerMm : boardCornersMm(board)) {
      const glm::dvec3 p = cameraFromBoardMm(pose, cornerMm);
      const double thetaDeg = degrees(std::atan2(std::hypot(p.x, p.y), p.z));
      c.minCornerThetaDeg = std::min(c.minCornerThetaDeg, thetaDeg);
      c.maxCornerThetaDeg = std::max(c.maxCornerThetaDeg, thetaDeg);
      beyondNinety = beyondNinety || thetaDeg > 90.0;
      EXPECT_GT(glm::dot(frontNormal, -glm::normalize(p)), std::cos(testing::radians(60.5)))
          << "a corner seen from behind or edge-on";
      if (thetaDeg > degrees(lens.maxThetaRad) - 8.0) {
        quadrant[(p.x > 0.0 ? 1 : 0) + (p.y > 0.0 ? 2 : 0)] = true;
      }
    }
    // The margin's outline, and so the whole board, inside the circle (1 degree in) and sensor.
    for (int i = 0; i <= 40; ++i) {
      const double t = i / 40.0;
      for (const glm::dvec2 q :
           {glm::dvec2(-2.0 + 12.0 * t, -2.0), glm::dvec2(-2.0 + 12.0 * t, 7.0),
            glm::dvec2(-2.0, -2.0 + 9.0 * t), glm::dvec2(10.0, -2.0 + 9.0 * t)}) {
        const glm::dvec3 p = cameraFromBoardMm(pose, glm::dvec3(q * board.squareMm, 0.0));
        EXPECT_LT(std::atan2(std::hypot(p.x, p.y), p.z), lens.maxThetaRad - testing::radians(0.99));
        const glm::dvec2 s = *lens.sensorFromCamera(p);
        EXPECT_TRUE(s.x > 0.0 && s.y > 0.0 && s.x < 799.0 && s.y < 799.0) << s.x << ", " << s.y;
      }
    }
    c.viewsBeyondNinety += beyondNinety ? 1 : 0;
  }
  c.quadrantsAtRim = int(std::count(std::begin(quadrant), std::end(quadrant), true));
  return c;
}

TEST(BoardPoses, RimLeftUnconstrainedWhenPosesIgnoreTheLensWidth) {
  const Checkerboard board = testing::testBoard();
  for (double fovDeg : {190.0, 200.0}) {
    const KannalaBrandtLens lens = testing::fisheyeTruthLens(fovDeg);
    const auto poses = boardPosesCoveringLens(board, lens, 800, 800, 12, 7);
    ASSERT_EQ(poses.size(), 12u);
    const Coverage c = checkPoses(lens, poses, board);
    std::printf("%g-degree lens: corners from %.1f to %.1f deg, %d views beyond 90 deg\n", fovDeg,
                c.minCornerThetaDeg, c.maxCornerThetaDeg, c.viewsBeyondNinety);
    EXPECT_LT(c.minCornerThetaDeg, 5.0) << "the centre";
    EXPECT_GT(c.maxCornerThetaDeg, degrees(lens.maxThetaRad) - 6.0) << "near the rim";
    EXPECT_EQ(c.quadrantsAtRim, 4) << "the rim all around";
    if (fovDeg >= 200.0) {
      EXPECT_GE(c.viewsBeyondNinety, 3) << "behind the lens's plane";
    }
  }
}

TEST(BoardPoses, PosesChangeBetweenRunsWhenTheSeedIsIgnored) {
  const Checkerboard board = testing::testBoard();
  const KannalaBrandtLens lens = testing::fisheyeTruthLens(190.0);
  const auto a = boardPosesCoveringLens(board, lens, 800, 800, 6, 3);
  const auto b = boardPosesCoveringLens(board, lens, 800, 800, 6, 3);
  const auto c = boardPosesCoveringLens(board, lens, 800, 800, 6, 4);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].cameraFromBoard, b[i].cameraFromBoard);
    EXPECT_EQ(a[i].boardOriginCameraMm, b[i].boardOriginCameraMm);
  }
  EXPECT_NE(a[3].boardOriginCameraMm, c[3].boardOriginCameraMm);
}

}  // namespace
}  // namespace vem::calib
