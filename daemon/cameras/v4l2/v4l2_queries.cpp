#include "cameras/v4l2/v4l2_queries.h"

#include <linux/videodev2.h>

#include <cstring>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

constexpr std::uint32_t kMaxEnumerated = 256;

std::string fixedString(const std::uint8_t* text, std::size_t size) {
  const char* chars = reinterpret_cast<const char*>(text);
  return std::string(chars, ::strnlen(chars, size));
}

}  // namespace

std::expected<V4l2Identity, std::string> queryCaptureIdentity(V4l2Device& device,
                                                              const std::string& path) {
  v4l2_capability cap{};
  if (const int error = v4l2Ioctl(device, VIDIOC_QUERYCAP, &cap)) {
    return std::unexpected(
        fmt::format("{} is not a V4L2 device (VIDIOC_QUERYCAP: {})", path, errnoText(error)));
  }
  const std::uint32_t caps =
      (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
  if (!(caps & V4L2_CAP_VIDEO_CAPTURE)) {
    return std::unexpected(fmt::format("{} is not a single-planar video capture device{}", path,
                                       (caps & V4L2_CAP_VIDEO_CAPTURE_MPLANE)
                                           ? " (it is multi-planar, which vemd does not read)"
                                           : " (a metadata or output node?)"));
  }
  if (!(caps & V4L2_CAP_STREAMING)) {
    return std::unexpected(fmt::format("{} cannot stream (no V4L2_CAP_STREAMING)", path));
  }
  return V4l2Identity{fixedString(cap.card, sizeof cap.card),
                      fixedString(cap.bus_info, sizeof cap.bus_info),
                      fixedString(cap.driver, sizeof cap.driver)};
}

std::vector<std::uint32_t> enumerateFormats(V4l2Device& device) {
  std::vector<std::uint32_t> formats;
  for (std::uint32_t i = 0; i < kMaxEnumerated; ++i) {
    v4l2_fmtdesc desc{};
    desc.index = i;
    desc.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (v4l2Ioctl(device, VIDIOC_ENUM_FMT, &desc) != 0) break;
    formats.push_back(desc.pixelformat);
  }
  return formats;
}

std::vector<V4l2FrameSize> enumerateFrameSizes(V4l2Device& device, std::uint32_t fourcc) {
  std::vector<V4l2FrameSize> sizes;
  for (std::uint32_t i = 0; i < kMaxEnumerated; ++i) {
    v4l2_frmsizeenum size{};
    size.index = i;
    size.pixel_format = fourcc;
    if (v4l2Ioctl(device, VIDIOC_ENUM_FRAMESIZES, &size) != 0) break;
    if (size.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
      sizes.push_back({int(size.discrete.width), int(size.discrete.height)});
    } else {
      sizes.push_back({int(size.stepwise.max_width), int(size.stepwise.max_height)});
      break;
    }
  }
  return sizes;
}

}  // namespace vem::cameras
