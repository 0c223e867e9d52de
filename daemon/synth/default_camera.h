// The camera synthetic recordings use when none is given: config/camera-example.toml (a 1280 x 1024
// RGB12 log sensor over 1e-3 to 1e5 cd/m^2 behind a 190-degree fisheye looking straight up),
// embedded in the library at configure time (daemon/synth/CMakeLists.txt reads the file), so the
// tools run without the source tree and the default cannot drift from the file. Parse it with
// calib::io::parseCameraFile(std::string(exampleCameraToml()), kExampleCameraSource).
#pragma once

#include <string_view>

namespace vem::synth {

inline constexpr std::string_view kExampleCameraSource = "the built-in example camera";

// The whole TOML text of config/camera-example.toml, byte for byte.
[[nodiscard]] std::string_view exampleCameraToml();

}  // namespace vem::synth
