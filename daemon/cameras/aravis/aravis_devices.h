// listAravisDevices: the GenICam cameras Aravis can see, for `vemd --list-devices`.
//
// WARNING: this runs Aravis's discovery (arv_update_device_list): it enumerates USB3 Vision
// devices and BROADCASTS a GigE Vision discovery packet on every network interface of the host,
// which every GigE Vision camera on those networks answers. Opening a camera by address
// (aravis_source.h) does not.
//
// Each DeviceInfo: spec "aravis:DEVICE-ID" (the id Aravis opens it by), model "VENDOR MODEL",
// serial, and modes: the pixel formats the backend reads among those the camera offers, each with
// the camera's largest size ("Mono12 2048x1536 (as Mono12Packed)"). Cameras that cannot be opened
// (another host controls them, no USB permission) are listed without modes, with the reason in
// their model text.
#pragma once

#include <expected>
#include <string>
#include <vector>

#include "cameras/camera_settings.h"

namespace vem::cameras {

[[nodiscard]] std::expected<std::vector<DeviceInfo>, std::string> listAravisDevices();

}  // namespace vem::cameras
