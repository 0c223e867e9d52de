// Frame generators for FakeLibcameraPort (fake_libcamera_port.h): what the fake camera "sees".
// - patternFrames(): a deterministic pattern of every code of the format, different per pixel,
//   channel, sequence number and exposure; patternCode() gives any code of it, so a test checks
//   every pixel exactly.
// - syntheticFrames(): a synthetic scene (daemon/synth) seen through a calibrated camera, as vemd's
//   synthetic source renders it: frame `sequence` shows the scene at sequence / rateHz seconds,
//   taken with the frame's exposure and gain. Deterministic (no noise), so a test renders the same
//   frames again to compare.
#pragma once

#include <cstdint>
#include <string>

#include "calib/core/camera_calibration.h"
#include "fake_libcamera_port.h"
#include "frames/raw_frame.h"

namespace vem::cameras::testing {

[[nodiscard]] std::uint16_t patternCode(const FakeFrameParams& params, vem::PixelFormat format,
                                        int u, int v, int channel);
[[nodiscard]] FakeFrameGenerator patternFrames();

// `scene` as synth::makeScene names it ("sky", "clouds", ...); fails the process on a bad name
// (tests only).
[[nodiscard]] FakeFrameGenerator syntheticFrames(const calib::CameraCalibration& camera,
                                                 const std::string& scene, double rateHz);

}  // namespace vem::cameras::testing
