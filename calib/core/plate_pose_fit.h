// The plate camera's pose in the world (plate_camera.h) from one view of a checkerboard lying
// printed side up on the floor: the corners are undistorted through the intrinsics
// (idealFromDistortedPx) and cv::solvePnP finds the board's pose (IPPE, then Levenberg-Marquardt),
// which fixes the world: world X = board X, world Z = board Y, world Y = -board Z, origin at the
// board's first inner corner (in metres).
//
// The corners' order decides the board frame. detectCheckerboard keeps the board's handedness, so
// the board's +Z points into the floor and the camera is above it; corners in mirrored order (rows
// or columns reversed, as another detector may give them) would put the camera under the floor.
// Then the board frame is turned 180 degrees about its X axis (board Y and Z negated): the camera
// is above the floor again, the origin stays at the first corner as listed, and world Z then runs
// toward the corners listed first. When innerCols + innerRows is even the board looks the same
// turned by 180 degrees and its first corner may be either end of the grid: the world's origin and
// its X and Z axes follow the corners' order (docs/calibration.md, "Plate camera").
//
// Units: corners in pixels, the board's squares in mm, the pose in metres; RMS in pixels of the
// distorted image (boardReprojectionRmsPx).
#pragma once

#include <expected>
#include <span>

#include <glm/vec2.hpp>

#include "calib/core/checkerboard.h"
#include "calib/core/plate_camera.h"
#include "calib/core/plate_fit_failure.h"

namespace vem::calib {

struct PlatePoseFit {
  PlatePose pose;
  GeometricQuality quality;  // views 1; date left empty: the caller stamps it
  bool boardTurned = false;  // the corners came mirrored and the board frame was turned
};

// Refuses: a corner count that is not the board's, a pose OpenCV cannot find or with the board
// behind the camera, an RMS above maxRmsPx.
[[nodiscard]] std::expected<PlatePoseFit, PlateFitFailure> fitPlatePose(
    std::span<const glm::dvec2> corners, const Checkerboard& board,
    const PlateIntrinsics& intrinsics, double maxRmsPx);

// The floor board's pose in the camera frame (mm, checkerboard.h) for a camera at `pose`: the
// board of the world frame, printed side up, its first inner corner at the world's origin.
[[nodiscard]] BoardPose floorBoardPose(const PlatePose& pose);

}  // namespace vem::calib
