#include "calib/core/plate_pose_fit.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <glm/matrix.hpp>
#include <opencv2/calib3d.hpp>

#include "calib/core/plate_intrinsics_fit.h"
#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr double kMmPerM = 1000.0;

glm::dmat3 glmFromCv(const cv::Matx33d& m) {
  glm::dmat3 out;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) out[col][row] = m(row, col);
  return out;
}

// The board's pose in the camera frame (metres), from its undistorted corners.
std::optional<BoardPose> solveBoardPose(std::span<const glm::dvec2> corners,
                                        const Checkerboard& board,
                                        const PlateIntrinsics& intrinsics) {
  std::vector<cv::Point3d> object;
  for (const glm::dvec3& p : boardCornersMm(board)) object.emplace_back(p.x, p.y, p.z);
  std::vector<cv::Point2d> image;
  for (const glm::dvec2& p : idealFromDistortedPx(intrinsics, corners))
    image.emplace_back(p.x, p.y);
  const cv::Matx33d k(intrinsics.fxPx, 0.0, intrinsics.cxPx, 0.0, intrinsics.fyPx, intrinsics.cyPx,
                      0.0, 0.0, 1.0);
  cv::Vec3d rvec, tvec;
  try {
    if (!cv::solvePnP(object, image, k, cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_IPPE))
      return std::nullopt;
    cv::solvePnPRefineLM(
        object, image, k, cv::noArray(), rvec, tvec,
        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
  } catch (const cv::Exception&) {
    return std::nullopt;
  }
  cv::Matx33d r;
  cv::Rodrigues(rvec, r);
  return BoardPose{glmFromCv(r), glm::dvec3(tvec[0], tvec[1], tvec[2])};
}

PlatePose platePoseFrom(const glm::dmat3& cameraFromBoard, const glm::dvec3& boardOriginCameraMm) {
  PlatePose pose;
  pose.cameraFromWorld = cameraFromBoard * glm::transpose(worldFromBoard());
  pose.positionWorldM = -(glm::transpose(pose.cameraFromWorld) * boardOriginCameraMm) / kMmPerM;
  return pose;
}

}  // namespace

std::expected<PlatePoseFit, PlateFitFailure> fitPlatePose(std::span<const glm::dvec2> corners,
                                                          const Checkerboard& board,
                                                          const PlateIntrinsics& intrinsics,
                                                          double maxRmsPx) {
  VEM_EXPECTS(!intrinsicsDefect(intrinsics) && maxRmsPx > 0.0);
  const std::size_t expected = std::size_t(board.innerCols * board.innerRows);
  if (corners.size() != expected)
    return std::unexpected(
        PlateFitFailure{PlateFitRefusal::WrongCornerCount,
                        fmt::format("{} corners were found where the {}x{} board has {}",
                                    corners.size(), board.innerCols, board.innerRows, expected),
                        0});
  const std::optional<BoardPose> board0 = solveBoardPose(corners, board, intrinsics);
  if (!board0)
    return std::unexpected(PlateFitFailure{PlateFitRefusal::NotConverged,
                                           "OpenCV's solvePnP found no pose for the board", 0});
  if (!(board0->boardOriginCameraMm.z > 0.0))
    return std::unexpected(
        PlateFitFailure{PlateFitRefusal::Behind, "the board's pose puts it behind the camera", 0});
  PlatePoseFit fit;
  fit.quality.views = 1;
  fit.quality.corners = int(expected);
  fit.quality.rmsReprojectionPx = boardReprojectionRmsPx(corners, board, intrinsics, *board0);
  fit.pose = platePoseFrom(board0->cameraFromBoard, board0->boardOriginCameraMm);
  if (fit.pose.positionWorldM.y < 0.0) {
    // Mirrored corners: turn the board frame 180 degrees about its X axis (plate_pose_fit.h).
    const glm::dmat3 turn(glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, -1.0, 0.0),
                          glm::dvec3(0.0, 0.0, -1.0));
    fit.pose = platePoseFrom(board0->cameraFromBoard * turn, board0->boardOriginCameraMm);
    fit.boardTurned = true;
  }
  if (!(fit.quality.rmsReprojectionPx <= maxRmsPx))
    return std::unexpected(PlateFitFailure{
        PlateFitRefusal::ErrorTooHigh,
        fmt::format("the floor board's RMS reprojection error is {:.3f} px, above the limit of "
                    "{:g} px: are the intrinsics this camera's, at this zoom and focus?",
                    fit.quality.rmsReprojectionPx, maxRmsPx),
        0});
  return fit;
}

BoardPose floorBoardPose(const PlatePose& pose) {
  return BoardPose{pose.cameraFromWorld * worldFromBoard(),
                   cameraFromWorldM(pose, glm::dvec3(0.0)) * kMmPerM};
}

}  // namespace vem::calib
