// A plate-camera calibration in words (calib/core/plate_camera.h), for `vemcalib show`: the whole
// file, or each value beside a truth's with the differences that matter for compositing. Angles
// in degrees, positions in metres (differences in mm), pixels of the plate image.
#pragma once

#include <ostream>
#include <string>

#include "calib/core/plate_camera.h"

namespace vem::calibtool {

void printPlateCamera(std::ostream& out, const calib::PlateCamera& plate, const std::string& path);

// Each value beside the truth's; then, when both have a pose, where world points seen by the
// truth land in the fitted plate image: a 32 x 18 grid of the truth's pixels, each ray to the
// floor (y = 0) or 20 m out when it misses the floor, projected through the fitted intrinsics
// and pose; the largest and RMS distance in pixels.
void printPlateComparison(std::ostream& out, const calib::PlateCamera& fitted,
                          const std::string& path, const calib::PlateCamera& truth,
                          const std::string& truthPath);

}  // namespace vem::calibtool
