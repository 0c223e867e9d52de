#include "cameras/libcamera/libcamera_stream_choice.h"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"

namespace vem::cameras {

namespace {

int depthRank(const LibcameraPixelFormat& format) {
  const auto& taken = libcameraTakenFormats();
  return int(std::find(taken.begin(), taken.end(), format) - taken.begin());
}

int roleRank(LibcameraRole role, const PixelFormat& pixel) {
  if (role == LibcameraRole::Viewfinder) return 2;
  const bool rawFirst = pixel.channels == 1;
  return (role == LibcameraRole::Raw) == rawFirst ? 0 : 1;
}

LibcameraSize largest(const std::vector<LibcameraSize>& sizes) {
  LibcameraSize best;
  for (const LibcameraSize& s : sizes) {
    if (std::int64_t(s.widthPx) * s.heightPx > std::int64_t(best.widthPx) * best.heightPx) best = s;
  }
  return best;
}

std::string sizesText(const std::vector<LibcameraSize>& sizes) {
  if (sizes.empty()) return "?";
  std::string out;
  for (const LibcameraSize& s : sizes) {
    out += fmt::format("{}{}x{}", out.empty() ? "" : "/", s.widthPx, s.heightPx);
  }
  return out;
}

std::string takenNames() {
  std::string out;
  for (const LibcameraPixelFormat& f : libcameraTakenFormats()) {
    out += fmt::format("{}{}", out.empty() ? "" : ", ", libcameraFormatName(f));
  }
  return out;
}

}  // namespace

std::string libcameraOffer(const LibcameraCameraInfo& camera) {
  if (camera.formats.empty()) return "no stream format at all";
  std::string out;
  for (const LibcameraStreamFormats& f : camera.formats) {
    out += fmt::format("{}{} {} ({})", out.empty() ? "" : ", ", libcameraFormatName(f.format),
                       sizesText(f.sizes), libcameraRoleName(f.role));
  }
  return out;
}

std::vector<std::string> libcameraModes(const LibcameraCameraInfo& camera) {
  std::vector<std::string> modes;
  for (const LibcameraStreamFormats& f : camera.formats) {
    const auto pixel = calibFormatOf(f.format);
    if (!pixel) continue;
    for (const LibcameraSize& s : f.sizes) {
      std::string mode =
          fmt::format("{} {}x{} ({}, {})", pixelFormatName(*pixel), s.widthPx, s.heightPx,
                      libcameraFormatName(f.format), libcameraRoleName(f.role));
      if (std::find(modes.begin(), modes.end(), mode) == modes.end()) modes.push_back(mode);
    }
  }
  return modes;
}

std::expected<LibcameraStreamConfig, std::string> chooseLibcameraStream(
    const LibcameraCameraInfo& camera, const CameraSettings& settings, const std::string& spec) {
  std::optional<PixelFormat> wanted;
  if (!settings.pixelFormat.empty()) {
    wanted = parsePixelFormat(settings.pixelFormat);
    if (!wanted) {
      return std::unexpected(fmt::format(
          "{}: the camera pixel format \"{}\" is not one of Mono8, Mono10, Mono12, Mono16, RGB8",
          spec, settings.pixelFormat));
    }
  }
  const LibcameraStreamFormats* best = nullptr;
  auto rank = [](const LibcameraStreamFormats& f) {
    return std::pair{depthRank(f.format), roleRank(f.role, *calibFormatOf(f.format))};
  };
  for (const LibcameraStreamFormats& f : camera.formats) {
    const auto pixel = calibFormatOf(f.format);
    if (!pixel || (wanted && *pixel != *wanted) || f.sizes.empty()) continue;
    if (!best || rank(f) < rank(*best)) best = &f;
  }
  if (!best) {
    return std::unexpected(
        fmt::format("{} ({}) offers no format that gives {}: it offers {}, and vemd takes {}", spec,
                    camera.model.empty() ? camera.id : camera.model,
                    wanted ? pixelFormatName(*wanted) : std::string("any pixel format vemd takes"),
                    libcameraOffer(camera), takenNames()));
  }
  LibcameraStreamConfig config;
  config.role = best->role;
  config.format = best->format;
  config.size = settings.widthPx > 0 && settings.heightPx > 0
                    ? LibcameraSize{settings.widthPx, settings.heightPx}
                    : largest(best->sizes);
  config.bufferCount = std::max(2, settings.buffers);
  return config;
}

}  // namespace vem::cameras
