// Frames of the synthetic `sky` scene (daemon/synth) as a small simulated fisheye camera delivers
// them, for the Aravis tests and bench: the test camera (tests/support/test_cameras.h: a log
// sensor behind a 190-degree lens looking straight up) at the given size and pixel format, its
// response scaled to the format's code range.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "frames/raw_frame.h"

namespace vem::testing {

struct SkyFrames {
  std::string cameraToml;               // the camera file of the simulated camera
  std::vector<vem::RawFrame> frames;    // scene times 0, 4, 8, ... s: every frame differs
  std::vector<glm::dvec3> sunDirWorld;  // per frame, unit
};

[[nodiscard]] SkyFrames renderSkyFrames(int widthPx, int heightPx, vem::PixelFormat format,
                                        int count);

}  // namespace vem::testing
