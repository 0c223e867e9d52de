// The cameras libcamera can see, for `vemd --list-devices`: one DeviceInfo per camera, spec
// "libcamera:ID", the model libcamera reports, no serial (libcamera 0.0.3 reports none), and the
// modes vemd can capture ("Mono16 1280x1024 (R16, Raw)"). An empty list is not an error.
#pragma once

#include <expected>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"
#include "cameras/libcamera/libcamera_port.h"

namespace vem::cameras {

[[nodiscard]] std::expected<std::vector<DeviceInfo>, std::string> listLibcameraDevices(
    LibcameraCameraPort& port);
// Through libcamera itself (libcamera_system_port.h).
[[nodiscard]] std::expected<std::vector<DeviceInfo>, std::string> listLibcameraDevices();

}  // namespace vem::cameras
