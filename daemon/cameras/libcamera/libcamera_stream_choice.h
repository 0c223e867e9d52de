// Which stream vemd asks a libcamera camera for, from what the camera offers
// (LibcameraCameraInfo) and what the user asked (CameraSettings). Pure.
//
// - The format: the one giving settings.pixelFormat ("Mono16", ...), or when that is "" the
//   deepest vemd takes (R16, R12, R10, RGB888, BGR888, R8: libcamera_pixel_layout.h). Mono formats
//   prefer the Raw role (the sensor's own codes, unprocessed), RGB formats VideoRecording, then
//   Viewfinder.
// - The size: settings' when given, else the largest the camera lists for that format.
// - Buffers: settings.buffers, at least 2.
#pragma once

#include <expected>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "cameras/libcamera/libcamera_port.h"

namespace vem::cameras {

// The stream to configure, or one sentence naming what the camera offers when nothing fits.
[[nodiscard]] std::expected<LibcameraStreamConfig, std::string> chooseLibcameraStream(
    const LibcameraCameraInfo& camera, const CameraSettings& settings, const std::string& spec);

// The modes vemd can capture from `camera`, for DeviceInfo::modes: "Mono16 1280x1024 (R16, Raw)".
[[nodiscard]] std::vector<std::string> libcameraModes(const LibcameraCameraInfo& camera);

// What the camera offers, for messages: "R8 640x480 (Raw), YUYV 1920x1080 (VideoRecording)".
[[nodiscard]] std::string libcameraOffer(const LibcameraCameraInfo& camera);

}  // namespace vem::cameras
