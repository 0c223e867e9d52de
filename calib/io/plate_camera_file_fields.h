// The names and units of the plate-camera file's fields (internal to vem_calibio), shared by its
// reader (plate_camera_file.cpp) and writer (plate_camera_file_format.cpp).
#pragma once

#include <string_view>

namespace vem::calib::io::detail {

inline constexpr std::string_view kUnitOne = "1";  // a pure number: distortion, rotation
inline constexpr std::string_view kUnitMetre = "m";
inline constexpr std::string_view kUnitColourGain = "linear/(cd/m2)";

// A camera_from_world whose rows are orthonormal to this tolerance, determinant +1, is a rotation.
inline constexpr double kRotationTolerance = 1e-6;

}  // namespace vem::calib::io::detail
