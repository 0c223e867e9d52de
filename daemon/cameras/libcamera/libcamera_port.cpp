#include "cameras/libcamera/libcamera_port.h"

#include <cstring>

#include <fmt/format.h>

#include "cameras/libcamera/libcamera_pixel_layout.h"

namespace vem::cameras {

namespace {

struct NamedFormat {
  LibcameraPixelFormat format;
  const char* name;
};

// libcamera's names (formats.h) for the formats a camera is likely to offer.
constexpr std::uint64_t kCsi2Packed = (std::uint64_t(11) << 56) | 1;  // MIPI vendor, packed
constexpr NamedFormat kNames[] = {
    {kLibcameraR8, "R8"},
    {kLibcameraR10, "R10"},
    {kLibcameraR12, "R12"},
    {kLibcameraR16, "R16"},
    {{drmFourcc('R', '1', '0', ' '), kCsi2Packed}, "R10_CSI2P"},
    {kLibcameraRGB888, "RGB888"},
    {kLibcameraBGR888, "BGR888"},
    {{drmFourcc('X', 'R', '2', '4'), 0}, "XRGB8888"},
    {{drmFourcc('X', 'B', '2', '4'), 0}, "XBGR8888"},
    {{drmFourcc('R', 'G', '1', '6'), 0}, "RGB565"},
    {{drmFourcc('Y', 'U', 'Y', 'V'), 0}, "YUYV"},
    {{drmFourcc('U', 'Y', 'V', 'Y'), 0}, "UYVY"},
    {{drmFourcc('N', 'V', '1', '2'), 0}, "NV12"},
    {{drmFourcc('N', 'V', '2', '1'), 0}, "NV21"},
    {{drmFourcc('Y', 'U', '1', '2'), 0}, "YUV420"},
    {{drmFourcc('M', 'J', 'P', 'G'), 0}, "MJPEG"},
    {{drmFourcc('R', 'G', 'G', 'B'), 0}, "SRGGB8"},
    {{drmFourcc('B', 'A', '8', '1'), 0}, "SBGGR8"},
    {{drmFourcc('R', 'G', '1', '0'), 0}, "SRGGB10"},
    {{drmFourcc('B', 'G', '1', '0'), 0}, "SBGGR10"},
    {{drmFourcc('R', 'G', '1', '0'), kCsi2Packed}, "SRGGB10_CSI2P"},
    {{drmFourcc('B', 'G', '1', '0'), kCsi2Packed}, "SBGGR10_CSI2P"},
    {{drmFourcc('R', 'G', '1', '2'), 0}, "SRGGB12"},
    {{drmFourcc('B', 'G', '1', '2'), 0}, "SBGGR12"},
    {{drmFourcc('R', 'G', '1', '2'), kCsi2Packed}, "SRGGB12_CSI2P"},
    {{drmFourcc('B', 'G', '1', '2'), kCsi2Packed}, "SBGGR12_CSI2P"},
};

}  // namespace

const char* libcameraRoleName(LibcameraRole role) {
  switch (role) {
    case LibcameraRole::Raw: return "Raw";
    case LibcameraRole::VideoRecording: return "VideoRecording";
    case LibcameraRole::Viewfinder: return "Viewfinder";
  }
  return "?";
}

std::string libcameraFormatName(const LibcameraPixelFormat& format) {
  for (const NamedFormat& n : kNames) {
    if (n.format == format) return n.name;
  }
  std::string chars;
  for (int i = 0; i < 4; ++i) {
    const char c = char((format.fourcc >> (8 * i)) & 0xffu);
    chars += (c >= 32 && c < 127) ? c : '?';
  }
  if (format.modifier == 0) return fmt::format("'{}'", chars);
  return fmt::format("'{}' (modifier {:#x})", chars, format.modifier);
}

std::string libcameraErrorName(int negativeErrno) {
  if (negativeErrno == 0) return "success";
  const char* text = strerrordesc_np(negativeErrno < 0 ? -negativeErrno : negativeErrno);
  return text ? text : fmt::format("error {}", negativeErrno);
}

}  // namespace vem::cameras
