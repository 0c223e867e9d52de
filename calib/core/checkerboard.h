// A planar checkerboard: the target of the geometric calibration (fisheye_fit.h; Kannala and Brandt
// 2006, section 4, after Zhang's planar calibration), its poses in front of the camera, and the raw
// frames a camera would take of it, for tests and `vemcalib simulate boards`.
//
// Conventions and units:
// - innerCols x innerRows inner corners (OpenCV's patternSize), squares of squareMm millimetres.
// - Board frame, mm: origin at the first inner corner, +X along a row (increasing column), +Y along
// a
//   column (increasing row), +Z into the board: the printed side faces -Z. Corner (col, row) sits
//   at (col, row, 0) * squareMm; corners are listed row-major, col fastest, as OpenCV lists them.
// - Squares: the one spanning [a, a+1] x [b, b+1] squares is black when a + b is even, for a in
//   [-1, innerCols - 1] and b in [-1, innerRows - 1]; so the square between corners (0, 0) and
//   (1, 1) is black, and so is the board's top-left square, as in OpenCV's printed pattern. A white
//   margin one square wide surrounds the squares.
// - A pose places the board in the camera frame of kannala_brandt.h:
//   p_camera = cameraFromBoard * p_board + boardOriginCameraMm. The identity rotation shows the
//   printed side upright, +X along the sensor's +u and +Y along +v.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/core/camera_simulator.h"
#include "calib/core/kannala_brandt.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct Checkerboard {
  int innerCols = 9;
  int innerRows = 6;
  double squareMm = 60.0;
};

struct BoardPose {
  glm::dmat3 cameraFromBoard{1.0};
  glm::dvec3 boardOriginCameraMm{0.0, 0.0, 1000.0};
};

// The inner corners in the board frame (mm, z = 0), row-major.
[[nodiscard]] std::vector<glm::dvec3> boardCornersMm(const Checkerboard& board);

// A board-frame point (mm) in the camera frame (mm).
[[nodiscard]] glm::dvec3 cameraFromBoardMm(const BoardPose& pose, const glm::dvec3& boardMm);

// The frame truth's camera takes of the board: each pixel averages options.supersamples^2 rays
// through truth.lens over its area. A ray reads whiteCdM2 or blackCdM2 where it meets the printed
// side (squares and margin), a mid grey sqrt(white * black) where it misses the board or meets its
// back, and 0 outside the lens circle; luminance (times options.radianceScale) becomes codes
// through SensorResponseSimulator, so response, noise, quantisation and clipping are the sensor's.
// Needs truth.lens and truth.photometric; size and format from truth.camera.
[[nodiscard]] RawFrame simulateBoardView(const Checkerboard& board, const BoardPose& pose,
                                         const CameraCalibration& truth,
                                         const SimulationOptions& options, double whiteCdM2,
                                         double blackCdM2);

// `count` poses whose corners, across the views, cover the lens's image circle from its centre to
// a few degrees inside maxThetaRad (beyond 90 degrees for lenses wider than 180). Each board,
// margin included, lies 1 degree inside the image circle and inside the width x height sensor,
// shows its printed side to the camera (no corner seen more than 60 degrees off the board's normal)
// and keeps neighbouring corners 8 pixels apart or more in the image, for the detector. View 0
// looks down the optical axis; later views move outward at golden-angle azimuths, boards spanning
// 60 to 80 degrees of view, tilted 16 to 40 degrees; from 60 % of the views on they reach the rim,
// all around it. Views past half way take the best of 12 draws (the one whose corners reach
// furthest out), with boards spanning 40 to 48 degrees. Deterministic in `seed`.
[[nodiscard]] std::vector<BoardPose> boardPosesCoveringLens(const Checkerboard& board,
                                                            const KannalaBrandtLens& lens,
                                                            int widthPx, int heightPx, int count,
                                                            std::uint64_t seed);

}  // namespace vem::calib
