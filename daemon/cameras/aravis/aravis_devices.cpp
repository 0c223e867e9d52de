#include "cameras/aravis/aravis_devices.h"

#include <arv.h>

#include <fmt/format.h>

#include "cameras/aravis/aravis_pixel_formats.h"
#include "cameras/aravis/glib_object.h"

namespace vem::cameras {

namespace {

std::string text(const char* value) {
  return value != nullptr ? std::string(value) : std::string();
}

std::vector<std::string> modesOf(ArvCamera* camera) {
  GErrorSlot error;
  guint count = 0;
  const char** names =
      arv_camera_dup_available_pixel_formats_as_strings(camera, &count, error.out());
  int minW = 0, maxW = 0, minH = 0, maxH = 0;
  arv_camera_get_width_bounds(camera, &minW, &maxW, nullptr);
  arv_camera_get_height_bounds(camera, &minH, &maxH, nullptr);
  std::vector<std::string> modes;
  for (guint i = 0; names != nullptr && i < count; ++i) {
    const NativePixelFormat* native = nativeFormatByName(names[i]);
    if (native == nullptr) continue;
    const std::string name = pixelFormatName(native->format);
    modes.push_back(name == native->genicamName
                        ? fmt::format("{} {}x{}", name, maxW, maxH)
                        : fmt::format("{} {}x{} (as {})", name, maxW, maxH, native->genicamName));
  }
  g_free(static_cast<void*>(names));
  return modes;
}

DeviceInfo describeDevice(unsigned index) {
  DeviceInfo info;
  const std::string id = text(arv_get_device_id(index));
  info.spec = "aravis:" + id;
  info.model =
      fmt::format("{} {}", text(arv_get_device_vendor(index)), text(arv_get_device_model(index)));
  info.serial = text(arv_get_device_serial_nbr(index));
  GErrorSlot error;
  GObjectPtr<ArvCamera> camera(arv_camera_new(id.c_str(), error.out()));
  if (!camera) {
    info.model +=
        fmt::format(" (cannot be opened: {})", error ? error.message() : "no reason given");
    return info;
  }
  info.modes = modesOf(camera.get());
  return info;
}

}  // namespace

std::expected<std::vector<DeviceInfo>, std::string> listAravisDevices() {
  arv_update_device_list();
  std::vector<DeviceInfo> devices;
  const unsigned count = arv_get_n_devices();
  for (unsigned i = 0; i < count; ++i) devices.push_back(describeDevice(i));
  return devices;
}

}  // namespace vem::cameras
