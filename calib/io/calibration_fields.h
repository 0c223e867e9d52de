// Fields that the camera file (camera_file.h) and the plate-camera file (plate_camera_file.h) share
// (internal to vem_calibio): the [camera] table, a geometric fit's quality and angles written in
// degrees that read back exactly. One copy, read and written the same way in both files.
#pragma once

#include <string_view>

#include <glm/vec2.hpp>

#include "calib/core/camera_calibration.h"
#include "calib/io/toml_writer.h"
#include "util/toml_reader.h"

namespace vem::calib::io::detail {

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
