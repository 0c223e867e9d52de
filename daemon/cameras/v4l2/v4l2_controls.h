// Exposure, gain and frame rate of a V4L2 camera: the unit conversions (pure) and the ioctls that
// apply them.
//
// - Exposure: V4L2_CID_EXPOSURE_AUTO is set to V4L2_EXPOSURE_MANUAL (or, when the menu lacks it,
//   V4L2_EXPOSURE_SHUTTER_PRIORITY), then V4L2_CID_EXPOSURE_ABSOLUTE, whose unit V4L2 defines as
//   100 us: value = round(exposureUs / 100), clamped to the control's range and step. A camera
//   with only V4L2_CID_EXPOSURE (a driver-defined unit, often sensor lines) is refused.
// - Gain: V4L2_CID_ANALOGUE_GAIN when the driver has it, else V4L2_CID_GAIN. V4L2 defines no unit
//   for either, so the mapping is an assumption: the control is taken as linear in its value with
//   the driver's default value meaning unity (1x); value = round(gain x default) clamped to the
//   range and step (unity = 1 when the default is 0). Many sensor drivers code gain otherwise
//   (dB steps, 1 / (1 - x) tables): calibrate such a camera at the gain it will run with.
// - Frame rate: VIDIOC_S_PARM's timeperframe (seconds per frame = numerator / denominator); the
//   driver picks the nearest interval it supports; the rate in force is read back.
// Every applied value is read back: what the camera really took, in our units.
#pragma once

#include <linux/videodev2.h>

#include <expected>
#include <optional>
#include <string>

#include "cameras/v4l2/v4l2_device.h"

namespace vem::cameras {

inline constexpr double kExposureAbsoluteUnitUs = 100.0;  // V4L2_CID_EXPOSURE_ABSOLUTE

// `wanted` rounded to the control's step (from its minimum) and clamped to its range.
[[nodiscard]] int controlValueNear(double wanted, const v4l2_queryctrl& control);
// The gain control's value meaning unity (1x): its default, or 1 when the default is 0 or below.
[[nodiscard]] int gainUnityValue(const v4l2_queryctrl& control);

// The control `id`'s description, or nullopt when the driver has none (or it is disabled).
[[nodiscard]] std::optional<v4l2_queryctrl> queryControl(V4l2Device& device, std::uint32_t id);

// Manual exposure of about exposureUs; the exposure in force (us), or a sentence fragment
// ("the camera has no V4L2_CID_EXPOSURE_ABSOLUTE control").
[[nodiscard]] std::expected<double, std::string> applyExposureUs(V4l2Device& device,
                                                                 double exposureUs);
// Gain of about `gain` (linear); the gain in force, or a sentence fragment.
[[nodiscard]] std::expected<double, std::string> applyGain(V4l2Device& device, double gain);
// The exposure (us) and gain (linear) in force, when the camera has the controls.
[[nodiscard]] std::optional<double> currentExposureUs(V4l2Device& device);
[[nodiscard]] std::optional<double> currentGain(V4l2Device& device);

// Frame rate of about rateHz; the rate in force (Hz), or a sentence fragment.
[[nodiscard]] std::expected<double, std::string> applyFrameRate(V4l2Device& device, double rateHz);
// The rate in force (VIDIOC_G_PARM), or nullopt when the driver does not say.
[[nodiscard]] std::optional<double> currentFrameRate(V4l2Device& device);

}  // namespace vem::cameras
