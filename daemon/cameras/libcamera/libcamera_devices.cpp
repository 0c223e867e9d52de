#include "cameras/libcamera/libcamera_devices.h"

#include "cameras/libcamera/libcamera_stream_choice.h"
#include "cameras/libcamera/libcamera_system_port.h"

namespace vem::cameras {

std::expected<std::vector<DeviceInfo>, std::string> listLibcameraDevices(
    LibcameraCameraPort& port) {
  auto cameras = port.listCameras();
  if (!cameras) return std::unexpected(cameras.error());
  std::vector<DeviceInfo> devices;
  for (const LibcameraCameraInfo& camera : *cameras) {
    devices.push_back({"libcamera:" + camera.id, camera.model, "", libcameraModes(camera)});
  }
  return devices;
}

std::expected<std::vector<DeviceInfo>, std::string> listLibcameraDevices() {
  auto port = makeLibcameraSystemPort();
  if (!port) return std::unexpected(port.error());
  return listLibcameraDevices(**port);
}

}  // namespace vem::cameras
