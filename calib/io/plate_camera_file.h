// Plate-camera files (calib/core/plate_camera.h): TOML, versioned, written by `vemcalib plate ...`
// and read by the renderer that composites into the plate. docs/calibration.md, "Plate camera",
// shows a whole file and lists every field with its unit.
//
// Format (version 1):
//   format = "vemcast-plate-camera"      version = 1
//   [camera]          model, serial, sensor_width and sensor_height in "px", pixel_format
//   [intrinsics]      model = "brown-conrady" | "kannala-brandt", focal_length = [fx, fy] and
//                     principal_point = [cx, cy] in "px", distortion in "1" (5 or 4 values),
//                     [intrinsics.fit] rms reprojection in "px", views, corners, date
//   [pose]            (optional) camera_from_world (3 rows) in "1", position in "m",
//                     [pose.fit] as [intrinsics.fit]
//   [probe]           (optional) yaw in "deg" (also "rad"), date
//   [colour]          (optional) gain in "linear/(cd/m2)", rms_residual in "%", patches, date
// Every quantity with a unit is an inline table { value = ..., unit = "..." }; the loader accepts
// exactly the unit the field names and refuses others.
//
// Loading refuses, in one sentence naming the file and the field: no file, not TOML, another
// format (a light-probe camera file given by mistake is named as such), an unknown version, a
// missing or unknown field, a wrong unit or type, a value out of range (a principal point off the
// sensor, a focal length not above 0, a camera_from_world that is not a rotation, a camera not
// above the floor, a gain not above 0). Saving is atomic and checks the new file with the loader
// first: the old file stays until the new one is complete.
#pragma once

#include <expected>
#include <filesystem>
#include <string>

#include "calib/core/plate_camera.h"
#include "calib/io/calib_file_failure.h"

namespace vem::calib::io {

inline constexpr int kPlateCameraFileVersion = 1;

[[nodiscard]] std::expected<PlateCamera, CalibFileFailure> loadPlateCameraFile(
    const std::filesystem::path& path);

// Parses TOML text; `sourceName` names it in messages.
[[nodiscard]] std::expected<PlateCamera, CalibFileFailure> parsePlateCameraFile(
    const std::string& text, const std::string& sourceName);

// The intrinsics' size must be the camera's sensor size.
[[nodiscard]] std::string formatPlateCameraFile(const PlateCamera& plate);

[[nodiscard]] std::expected<void, CalibFileFailure> savePlateCameraFile(
    const PlateCamera& plate, const std::filesystem::path& path);

}  // namespace vem::calib::io
