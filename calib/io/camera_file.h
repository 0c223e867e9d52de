// Camera calibration files: TOML, versioned, written by vemcalib and read by vemd. docs/calibration.md
// shows a whole file and lists every field with its unit.
//
// Format (version 1):
//   format = "vemcast-camera"      version = 1
//   [camera]       model, serial, sensor_width = {value, unit="px"}, sensor_height, pixel_format
//   [photometric]  (optional) model = "log" | "linear" | "table", black_level and saturation in
//                  "code", per-model parameters with units, [photometric.fit] residuals and date
//   [geometric]    (optional) model = "kannala-brandt", k = {value=[k1..k5], unit="px"},
//                  principal_point in "px", aspect (plain number), max_theta in "deg",
//                  [geometric.fit] rms reprojection in "px", views, corners, date
//   [orientation]  image_rotation, tilt, tilt_azimuth in "deg"
// Every quantity with a unit is an inline table { value = ..., unit = "..." }; the loader accepts
// exactly the unit the field names ("deg" also as "rad", converted) and refuses others.
//
// Loading refuses, naming the file and the field: a file that is not TOML, another format or an
// unknown version, a missing field, a wrong unit, a value of the wrong type or out of range, a lens
// whose r(theta) does not increase up to max_theta. Saving is atomic: the old file stays until the
// new one is complete.
#pragma once

#include <expected>
#include <filesystem>
#include <string>

#include "calib/core/camera_calibration.h"
#include "calib/io/calib_file_failure.h"

namespace vem::calib::io {

inline constexpr int kCameraFileVersion = 1;

[[nodiscard]] std::expected<CameraCalibration, CalibFileFailure> loadCameraFile(
    const std::filesystem::path& path);

// Parses TOML text; `sourceName` names it in messages.
[[nodiscard]] std::expected<CameraCalibration, CalibFileFailure> parseCameraFile(
    const std::string& text, const std::string& sourceName);

[[nodiscard]] std::string formatCameraFile(const CameraCalibration& calibration);

[[nodiscard]] std::expected<void, CalibFileFailure> saveCameraFile(
    const CameraCalibration& calibration, const std::filesystem::path& path);

}  // namespace vem::calib::io
