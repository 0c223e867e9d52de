#include "cameras/v4l2/v4l2_device_list.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "cameras/v4l2/v4l2_formats.h"
#include "cameras/v4l2/v4l2_queries.h"

namespace vem::cameras {

namespace fs = std::filesystem;

namespace {

std::optional<int> videoNumber(const std::string& filename) {
  constexpr std::string_view kPrefix = "video";
  if (!filename.starts_with(kPrefix) || filename.size() == kPrefix.size()) return std::nullopt;
  int number = 0;
  const char* first = filename.data() + kPrefix.size();
  const char* last = filename.data() + filename.size();
  auto [end, error] = std::from_chars(first, last, number);
  if (error != std::errc() || end != last) return std::nullopt;
  return number;
}

std::vector<std::string> modesOf(V4l2Device& device) {
  std::vector<std::string> modes;
  for (std::uint32_t fourcc : enumerateFormats(device)) {
    const auto output = outputFormatOf(fourcc, "");
    const std::string as =
        output ? fmt::format("as {}", pixelFormatName(*output)) : std::string("not readable");
    const auto sizes = enumerateFrameSizes(device, fourcc);
    if (sizes.empty()) modes.push_back(fmt::format("{} ({})", fourccName(fourcc), as));
    for (const V4l2FrameSize& s : sizes) {
      modes.push_back(fmt::format("{} {}x{} ({})", fourccName(fourcc), s.widthPx, s.heightPx, as));
    }
  }
  return modes;
}

}  // namespace

std::vector<std::string> videoNodePaths(const std::string& dir) {
  std::vector<std::pair<int, std::string>> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    if (auto n = videoNumber(entry.path().filename().string())) {
      found.emplace_back(*n, entry.path().string());
    }
  }
  std::ranges::sort(found);
  std::vector<std::string> paths;
  for (auto& [n, path] : found) paths.push_back(std::move(path));
  return paths;
}

std::expected<std::vector<DeviceInfo>, std::string> listV4l2Devices() {
  std::error_code error;
  fs::directory_iterator probe("/dev", error);
  if (error) return std::unexpected(fmt::format("cannot read /dev: {}", error.message()));
  return listV4l2Devices(videoNodePaths("/dev"),
                         [](const std::string& path) { return openSystemV4l2Device(path); });
}

std::vector<DeviceInfo> listV4l2Devices(const std::vector<std::string>& paths,
                                        const V4l2Opener& opener) {
  std::vector<DeviceInfo> devices;
  for (const std::string& path : paths) {
    auto device = opener(path);
    if (!device) {
      devices.push_back({"v4l2:" + path,
                         fmt::format("(cannot open {}: {})", path, errnoText(device.error())),
                         "",
                         {}});
      continue;
    }
    auto identity = queryCaptureIdentity(**device, path);
    if (!identity) continue;
    devices.push_back({"v4l2:" + path, identity->card, identity->busInfo, modesOf(**device)});
  }
  return devices;
}

std::expected<std::unique_ptr<V4l2Device>, int> openV4l2ByCardName(
    const std::string& name, const std::vector<std::string>& paths, const V4l2Opener& opener) {
  for (const std::string& path : paths) {
    auto device = opener(path);
    if (!device) continue;
    auto identity = queryCaptureIdentity(**device, path);
    if (identity && identity->card == name) return device;
  }
  return std::unexpected(ENOENT);
}

V4l2Opener systemV4l2Opener() {
  return [](const std::string& target) -> std::expected<std::unique_ptr<V4l2Device>, int> {
    if (target.starts_with("/")) return openSystemV4l2Device(target);
    return openV4l2ByCardName(target, videoNodePaths("/dev"),
                              [](const std::string& path) { return openSystemV4l2Device(path); });
  };
}

}  // namespace vem::cameras
