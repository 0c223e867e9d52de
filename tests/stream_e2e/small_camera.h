// The camera file and processing settings the end-to-end stream tests and the stream benchmark run
// vemd's synthetic scenes with: a 320 x 256 RGB log camera with a 190-degree lens
// (tests/support/test_cameras.h), so that rendering the scene, not streaming, never bounds vemd's
// rate (the example camera's 1280 x 1024 frames take tens of ms each to simulate on two cores).
#pragma once

#include <string>

namespace vem::e2e {

inline constexpr int kSmallCameraWidthPx = 320;
inline constexpr int kSmallCameraHeightPx = 256;

// The camera file's text (calib/io/camera_file.h's format).
[[nodiscard]] std::string smallCameraToml();

}  // namespace vem::e2e
