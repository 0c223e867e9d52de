// The names and units of the camera file's fields (internal to vem_calibio), shared by its reader
// (camera_file.cpp) and writer (camera_file_format.cpp), and by the plate-camera file's
// (plate_camera_file.cpp). docs/calibration.md lists them.
#pragma once

#include <string_view>

namespace vem::calib::io::detail {

inline constexpr std::string_view kCameraFormatName = "vemcast-camera";
// The plate camera's file (plate_camera_file.h): named when one file is given for the other.
inline constexpr std::string_view kPlateCameraFormatName = "vemcast-plate-camera";

inline constexpr std::string_view kUnitPx = "px";
inline constexpr std::string_view kUnitCode = "code";
inline constexpr std::string_view kUnitLogSlope = "code/ln(cd/m2)";     // log model: b
inline constexpr std::string_view kUnitLinearGain = "code/(cd/m2*us)";  // linear model: gain
inline constexpr std::string_view kUnitTableScale = "cd/m2*us";         // table model: scale
inline constexpr std::string_view kUnitRelative = "relative";           // table model: exposure
inline constexpr std::string_view kUnitDeg = "deg";
inline constexpr std::string_view kUnitPercent = "%";

inline constexpr std::string_view kLensModelName = "kannala-brandt";

// Largest sensor side accepted, in pixels (remap tables index sensor pixels with 32 bits).
inline constexpr int kMaxSensorSidePx = 32768;

}  // namespace vem::calib::io::detail
