#include "cameras/v4l2/v4l2_format_choice.h"

#include <linux/videodev2.h>

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cameras/v4l2/v4l2_queries.h"

namespace vem::cameras {

namespace {

std::string names(const std::vector<std::uint32_t>& fourccs) {
  std::vector<std::string> out;
  for (std::uint32_t f : fourccs) out.push_back(fourccName(f));
  return out.empty() ? std::string("no format") : fmt::format("{}", fmt::join(out, ", "));
}

std::expected<std::uint32_t, std::string> chooseFormat(V4l2Device& device,
                                                       const std::string& requested) {
  if (!requested.empty() && !parsePixelFormat(requested)) {
    return std::unexpected(fmt::format(
        "pixel format \"{}\" is not one of Mono8, Mono10, Mono12, Mono16, RGB8", requested));
  }
  const std::vector<std::uint32_t> offered = enumerateFormats(device);
  if (auto chosen = chooseNativeFormat(offered, requested)) return *chosen;
  const std::vector<std::uint32_t> wanted = nativeCandidates(requested);
  if (wanted.empty()) {
    return std::unexpected(fmt::format("no V4L2 format gives {}", requested));
  }
  return std::unexpected(fmt::format("the camera offers {}, not {} ({})", names(offered),
                                     requested.empty() ? "any format vemd reads" : requested,
                                     names(wanted)));
}

v4l2_format currentFormat(V4l2Device& device) {
  v4l2_format format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  (void)v4l2Ioctl(device, VIDIOC_G_FMT, &format);
  return format;
}

// The size to ask for: the settings', else the largest the driver lists, else the current one.
V4l2FrameSize wantedSize(V4l2Device& device, std::uint32_t fourcc, const CameraSettings& settings) {
  if (settings.widthPx > 0 && settings.heightPx > 0) return {settings.widthPx, settings.heightPx};
  const auto sizes = enumerateFrameSizes(device, fourcc);
  if (!sizes.empty()) {
    return *std::ranges::max_element(
        sizes, {}, [](const V4l2FrameSize& s) { return std::int64_t(s.widthPx) * s.heightPx; });
  }
  const v4l2_format current = currentFormat(device);
  return {int(current.fmt.pix.width), int(current.fmt.pix.height)};
}

}  // namespace

std::expected<V4l2Layout, std::string> setCaptureFormat(V4l2Device& device,
                                                        const CameraSettings& settings) {
  auto fourcc = chooseFormat(device, settings.pixelFormat);
  if (!fourcc) return std::unexpected(fourcc.error());
  const V4l2FrameSize size = wantedSize(device, *fourcc, settings);
  v4l2_format format{};
  format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  format.fmt.pix.width = std::uint32_t(size.widthPx);
  format.fmt.pix.height = std::uint32_t(size.heightPx);
  format.fmt.pix.pixelformat = *fourcc;
  format.fmt.pix.field = V4L2_FIELD_NONE;
  if (const int error = v4l2Ioctl(device, VIDIOC_S_FMT, &format)) {
    return std::unexpected(fmt::format("the camera refuses {} {}x{} (VIDIOC_S_FMT: {})",
                                       fourccName(*fourcc), size.widthPx, size.heightPx,
                                       errnoText(error)));
  }
  const v4l2_pix_format& got = format.fmt.pix;
  if (got.pixelformat != *fourcc || int(got.width) != size.widthPx ||
      int(got.height) != size.heightPx) {
    return std::unexpected(fmt::format("the camera offers {} {}x{}, not {} {}x{}",
                                       fourccName(got.pixelformat), got.width, got.height,
                                       fourccName(*fourcc), size.widthPx, size.heightPx));
  }
  V4l2Layout layout;
  layout.fourcc = *fourcc;
  layout.widthPx = size.widthPx;
  layout.heightPx = size.heightPx;
  layout.bytesPerLine =
      std::max<std::size_t>(got.bytesperline, packedRowBytes(*fourcc, size.widthPx));
  layout.output = *outputFormatOf(*fourcc, settings.pixelFormat);
  return layout;
}

}  // namespace vem::cameras
