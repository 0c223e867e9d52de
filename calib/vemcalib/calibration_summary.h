// A camera calibration in words, for people: `vemcalib show` prints all of it, `vemcalib
// photometric` the response it fitted. Luminance L in cd/m2, angles in degrees.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "calib/core/camera_calibration.h"

namespace vem::calibtool {

// One line per channel: "R: code = 1552 + 209 ln(L / 1 cd/m2)".
[[nodiscard]] std::vector<std::string> responseLines(
    const calib::PhotometricCalibration& photometric, PixelFormat format);

// "reads 0.0008 to 1.7e+05 cd/m2 (8.3 decades)": from the code above the black level to saturation,
// the range every channel reads.
[[nodiscard]] std::string readableRange(const calib::PhotometricCalibration& photometric,
                                        PixelFormat format, double exposureUs, double gain);

// Everything, section by section, as `vemcalib show` prints it.
void printCalibration(std::ostream& out, const calib::CameraCalibration& calibration,
                      const std::string& path);

}  // namespace vem::calibtool
