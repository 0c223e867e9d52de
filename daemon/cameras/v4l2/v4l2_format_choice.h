// Picking and setting the capture format of a V4L2 camera from CameraSettings
// (cameras/camera_settings.h): the native format that gives settings.pixelFormat (v4l2_formats.h)
// among those VIDIOC_ENUM_FMT offers, the size asked for (0 x 0: the largest VIDIOC_ENUM_FRAMESIZES
// lists, else the current one), then VIDIOC_S_FMT. A driver that adjusts the format or the size to
// something else is refused with one sentence fragment ("the camera offers YUYV 640x480, not Y16
// 1280x1024"): vemd's calibration is for one size and format. The driver's bytesperline is kept.
#pragma once

#include <expected>
#include <string>

#include "cameras/camera_settings.h"
#include "cameras/v4l2/v4l2_device.h"
#include "cameras/v4l2/v4l2_formats.h"

namespace vem::cameras {

[[nodiscard]] std::expected<V4l2Layout, std::string> setCaptureFormat(
    V4l2Device& device, const CameraSettings& settings);

}  // namespace vem::cameras
