// Raw frames as image files, for calibration input and simulated frames: 8- or 16-bit PNG, TIFF or
// PGM/PPM through OpenCV, grey (one channel) or colour (stored BGR by OpenCV, RGB here).
//
// A 16-bit file may hold codes of fewer bits (a Mono12 sensor): `bits` says how many; a code above
// 2^bits - 1 is then refused as a value error. Without `bits` the container's depth is used.
// Exposure and gain are not stored in the image: the caller supplies them (FILE@EXPOSURE_US on
// vemcalib's command line). Saving is atomic.
#pragma once

#include <expected>
#include <filesystem>
#include <optional>

#include "calib/io/calib_file_failure.h"
#include "frames/raw_frame.h"

namespace vem::calib::io {

[[nodiscard]] std::expected<RawFrame, CalibFileFailure> loadRawFrame(
    const std::filesystem::path& path, std::optional<int> bits = {});

// .png, .tif/.tiff, .pgm/.ppm; 8-bit formats store 8-bit files, others 16-bit.
[[nodiscard]] std::expected<void, CalibFileFailure> saveRawFrame(
    const RawFrame& frame, const std::filesystem::path& path);

}  // namespace vem::calib::io
