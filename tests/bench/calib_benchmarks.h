// Timings of the calibration applied per frame (calib/core/polar_remap.h): a 1280 x 1024 raw frame
// through the photometric table and the remap into a 1024 x 256 polar map, against the baseline of
// converting the whole frame to luminance and resampling it with OpenCV's cv::remap.
// Registered as "calib/<name>"; the report's calibration section reads them.
#pragma once

namespace vem::bench {

void registerCalibrationBenchmarks();

}  // namespace vem::bench
