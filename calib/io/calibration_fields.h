// Fields that the camera file (camera_file.h) and the plate-camera file (plate_camera_file.h) share
// (internal to vem_calibio): the format and version they open with, the [camera] table, a
// geometric fit's quality and angles written in degrees that read back exactly. One copy, read and
// written the same way in both files.
#pragma once

#include <cstdint>
#include <string_view>

#include <glm/vec2.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/io/toml_writer.h"
#include "util/toml_reader.h"

namespace vem::calib::io::detail {

// What a calibration file's `format` and `version` keys must hold, and what to say when they do
// not.
struct FileHeader {
  std::string_view formatName;   // "vemcast-camera"
  std::int64_t version;          // the one version this build reads
  std::string_view otherFormat;  // the other calibration file's format name
  std::string_view otherNote;    // after a refusal of otherFormat: " (a plate camera file, ...)"
  std::string_view foreignNote;  // after a refusal of any other: " (not a vemcast camera file)"
};

// format and version, read first: a newer file is refused for its version, not for its new fields.
void readFileHeader(util::TomlReader& root, const FileHeader& header);

// [camera]: model, serial, sensor_width and sensor_height in "px", pixel_format.
[[nodiscard]] CameraIdentity readCameraIdentity(util::TomlReader r);
void writeCameraIdentity(TomlWriter& w, const CameraIdentity& camera);

// principal_point = { value = [x, y], unit = "px" }, a point on the camera's sensor (pixel centres
// at integers, so from -0.5 to width - 0.5).
[[nodiscard]] glm::dvec2 readPrincipalPoint(util::TomlReader& r, const CameraIdentity& camera);

// A fit's table: rms_reprojection in "px", views, corners, date.
[[nodiscard]] GeometricQuality readGeometricQuality(util::TomlReader r);
void writeGeometricQuality(TomlWriter& w, std::string_view table, const GeometricQuality& quality);

// An angle as { value, unit = "deg" } that reads back (deg * pi / 180) as exactly `rad`, or in
// "rad" when no decimal degree value does.
void writeAngle(TomlWriter& w, std::string_view key, double rad, std::string_view note);

}  // namespace vem::calib::io::detail
