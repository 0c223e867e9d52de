// Finding a checkerboard (checkerboard.h) in a raw frame: the measurements of the geometric
// calibration (fisheye_fit.h; Kannala and Brandt 2006, section 4).
//
// Two steps. detectCheckerboard finds the board: the frame, of any pixel format (a 16-bit
// log-sensor frame included; a colour frame by its Rec. 709 weights of the channels' codes), is
// reduced to 8-bit grey by percentiles: each code becomes its rank among the frame's (histogram
// equalisation), which the black outside the image circle, bright lamps or a log sensor's
// compression cannot crush; OpenCV's findChessboardCornersSB finds the inner corners
// (findChessboardCorners and cornerSubPix are the fallback). Those corners are good to a few
// tenths of a pixel, and biased where a fisheye bends and squeezes the squares. refineCorners then
// measures each corner again once a lens and the board's pose are known (fisheye_fit.h): the
// corner's neighbourhood is resampled onto the board plane through lens and pose, where the squares
// are square and their edges straight whatever the lens, and the corner is the saddle point of a
// quadratic fitted to the smoothed patch (as ROCHADE does, Placht et al. 2014); mapped back through
// the same lens and pose, the result depends on them only to second order (after Datta et al.
// 2009, iterative refinement of control points).
//
// Conventions: corners in sensor coordinates of raw_frame.h (pixel centres at integers), listed in
// the board's order (boardCornersMm: row-major, col fastest). OpenCV may start from any end of the
// grid; the order is made consistent: the board's +X and +Y seen from its printed side keep their
// handedness in the image, and when innerCols + innerRows is odd the first corner is the one next
// to the black square, as on the board (when it is even, the board looks the same turned by 180
// degrees, and either order is a rigid turn of the board: a fit is unaffected).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "calib/core/checkerboard.h"
#include "calib/core/kannala_brandt.h"
#include "frames/raw_frame.h"

namespace vem::calib {

// The board's inner corners in the frame, or nullopt when the whole board is not found.
[[nodiscard]] std::optional<std::vector<glm::dvec2>> detectCheckerboard(const RawFrame& frame,
                                                                        const Checkerboard& board);

// `corners` (in the board's order) measured again on the board plane: each patch is centred on the
// board point whose image, through lens and pose, is the given corner, so the model need not put
// the corners where they are, only describe the board around them. A corner whose ray misses the
// board, whose patch leaves the frame or shows no saddle within 0.35 squares keeps its value.
[[nodiscard]] std::vector<glm::dvec2> refineCorners(const RawFrame& frame,
                                                    const Checkerboard& board,
                                                    const KannalaBrandtLens& lens,
                                                    const BoardPose& pose,
                                                    std::span<const glm::dvec2> corners);

}  // namespace vem::calib
