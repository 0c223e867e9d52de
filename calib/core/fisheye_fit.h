// Geometric calibration of a fisheye lens from checkerboard views (paper 004 section 5.1): the
// Kannala-Brandt model of kannala_brandt.h (Kannala and Brandt 2006, section 4) - k1..k5, principal
// point and aspect all free - and one board pose per view, fitted jointly by Levenberg-Marquardt
// (cv::LMSolver, Jacobian by central differences) on the corners' reprojection errors in pixels.
//
// The projection takes theta = atan2(hypot(x, y), z), so views beyond 90 degrees from the optical
// axis (lenses wider than 180 degrees) are fitted like any other. The start: an equidistant lens
// whose image circle fills the sensor's shorter side over the given field of view (then 1.6 times
// larger and smaller, if that start fails); each view's pose from its corners' rays, turned to a
// frame around their mean ray and solved there as a planar pinhole pose (cv::solvePnP, IPPE); then
// k1 and the principal point with the poses, then the whole lens. fitFisheyeRefined then measures
// the corners again on the board plane through the fit (board_detection.h) and fits again.
//
// Conventions and units: corners in sensor pixels (raw_frame.h), listed in the board's order
// (checkerboard.h, as detectCheckerboard returns them); board poses as checkerboard.h (mm); RMS
// errors in pixels: the root mean square over corners of the distance between the measured and
// the reprojected corner. The fitted lens's maxThetaRad is fovDeg / 2; it passes lensDefect.
#pragma once

#include <expected>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/core/checkerboard.h"
#include "calib/core/kannala_brandt.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct FisheyeFitOptions {
  double fovDeg = 190.0;  // the lens's full field of view, in (0, 360]
  int minViews = 4;       // fewer views with a board are refused
  double maxRmsPx = 1.0;  // largest RMS accepted, overall and for every view
};

struct FisheyeFit {
  KannalaBrandtLens lens;
  GeometricQuality quality;       // date left empty: the caller stamps it
  std::vector<double> viewRmsPx;  // per view, in the order given
  std::vector<BoardPose> poses;   // per view: where each board was
};

enum class FisheyeRefusal { TooFewViews, BoardNotFound, NotConverged, ErrorTooHigh, LensFolds };

struct FisheyeFitFailure {
  FisheyeRefusal cause;
  std::string message;  // one sentence naming the view and the limit
  int view = -1;        // the view at fault (index into the input), -1 when none is
};

// Fits the lens to each view's corners as given, without refining them: every list holds
// board.innerCols x board.innerRows corners in the board's order, seen by a widthPx x heightPx
// sensor.
[[nodiscard]] std::expected<FisheyeFit, FisheyeFitFailure> fitFisheye(
    std::span<const std::vector<glm::dvec2>> cornersPerView, const Checkerboard& board, int widthPx,
    int heightPx, const FisheyeFitOptions& options);

// The accurate fit for frames whose corners detectCheckerboard found: fits, measures every view's
// corners again on the board plane through that fit (refineCorners, board_detection.h), fits again
// (twice). The frames share one size; detectedCorners[i] belongs to frames[i].
[[nodiscard]] std::expected<FisheyeFit, FisheyeFitFailure> fitFisheyeRefined(
    std::span<const RawFrame> frames, std::span<const std::vector<glm::dvec2>> detectedCorners,
    const Checkerboard& board, const FisheyeFitOptions& options);

// Detects the board in every frame (board_detection.h), then fitFisheyeRefined; a frame without
// the whole board is refused (BoardNotFound, naming it).
[[nodiscard]] std::expected<FisheyeFit, FisheyeFitFailure> calibrateFisheye(
    std::span<const RawFrame> frames, const Checkerboard& board, const FisheyeFitOptions& options);

}  // namespace vem::calib
