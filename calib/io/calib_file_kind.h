// Which calibration file a path holds, by its `format` key: a light-probe camera file
// (camera_file.h) or a plate-camera file (plate_camera_file.h), for tools that take either
// (`vemcalib show`).
#pragma once

#include <filesystem>

namespace vem::calib::io {

enum class CalibFileKind { LightProbeCamera, PlateCamera, Unknown };

// Unknown when the file cannot be read, is not TOML or names another format: the loader of
// either kind then says why in one sentence.
[[nodiscard]] CalibFileKind calibFileKind(const std::filesystem::path& path);

}  // namespace vem::calib::io
