#include "vemd/device_list.h"

#include <expected>
#include <vector>

#include <fmt/format.h>

#include "cameras/aravis/aravis_devices.h"
#include "cameras/libcamera/libcamera_devices.h"
#include "cameras/v4l2/v4l2_device_list.h"

namespace vem::vemd {

namespace {

void appendBackend(std::string& text, std::string_view backend,
                   const std::expected<std::vector<cameras::DeviceInfo>, std::string>& devices) {
  if (!devices) {
    text += fmt::format("{}: cannot list cameras ({})\n", backend, devices.error());
    return;
  }
  if (devices->empty()) {
    text += fmt::format("{}: no camera\n", backend);
    return;
  }
  for (const cameras::DeviceInfo& d : *devices) {
    text += fmt::format("{}  {}{}\n", d.spec, d.model, d.serial.empty() ? "" : " (" + d.serial + ")");
    for (const std::string& mode : d.modes) text += fmt::format("    {}\n", mode);
  }
}

}  // namespace

std::string deviceListText() {
  std::string text;
  appendBackend(text, "aravis", cameras::listAravisDevices());
  appendBackend(text, "v4l2", cameras::listV4l2Devices());
  appendBackend(text, "libcamera", cameras::listLibcameraDevices());
  return text;
}

}  // namespace vem::vemd
