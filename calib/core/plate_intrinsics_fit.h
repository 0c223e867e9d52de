// The plate camera's intrinsics (plate_camera.h) from views of a planar checkerboard
// (checkerboard.h), as Zhang's method does it: cv::calibrateCamera for the BrownConrady model
// (k1, k2, p1, p2, k3 all free) or cv::fisheye::calibrate for KannalaBrandt (k1..k4, skew fixed at
// 0), each fitting one board pose per view with the lens by Levenberg-Marquardt.
//
// Conventions and units: corners in pixels (plate_camera.h), listed in the board's order
// (boardCornersMm, as detectCheckerboard returns them); RMS in pixels: the root mean square over
// corners of the distance between the measured corner and the board corner projected through the
// fitted intrinsics and its view's pose (plateFromCamera).
#pragma once

#include <expected>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "calib/core/checkerboard.h"
#include "calib/core/plate_camera.h"
#include "calib/core/plate_fit_failure.h"

namespace vem::calib {

struct PlateIntrinsicsFitOptions {
  PlateLensModel model = PlateLensModel::BrownConrady;
  int minViews = 3;       // fewer views are refused
  double maxRmsPx = 1.0;  // largest RMS accepted, overall and for every view
};

struct PlateIntrinsicsFit {
  PlateIntrinsics intrinsics;
  GeometricQuality quality;       // date left empty: the caller stamps it
  std::vector<double> viewRmsPx;  // per view, in the order given
  std::vector<BoardPose> poses;   // per view: where each board was (camera frame, mm)
};

// Fits the intrinsics of a widthPx x heightPx camera to each view's corners (innerCols x innerRows
// each). Refuses: too few views, a view with another number of corners, an OpenCV fit that fails
// or gives non-finite values, an RMS above the limit (overall or in a view, naming it).
[[nodiscard]] std::expected<PlateIntrinsicsFit, PlateFitFailure> fitPlateIntrinsics(
    std::span<const std::vector<glm::dvec2>> cornersPerView, const Checkerboard& board, int widthPx,
    int heightPx, const PlateIntrinsicsFitOptions& options);

// The RMS distance (px) between `corners` and the board's corners seen through `intrinsics` from
// `pose` (camera frame, mm); shared by the intrinsics and pose fits.
[[nodiscard]] double boardReprojectionRmsPx(std::span<const glm::dvec2> corners,
                                            const Checkerboard& board,
                                            const PlateIntrinsics& intrinsics,
                                            const BoardPose& pose);

}  // namespace vem::calib
