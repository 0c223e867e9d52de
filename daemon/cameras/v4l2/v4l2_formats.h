// The V4L2 pixel formats the backend reads, and what each becomes in calib's terms
// (daemon/frames/raw_frame.h). Pure: no device.
//
//   native (fourcc)        bytes per pixel / group           pipeline format
//   Y16  ('Y16 ')          2, little-endian                  Mono16
//   Y16_BE ('Y16 '|1<<31)  2, big-endian                     Mono16
//   Y12  ('Y12 ')          2, little-endian, 12 low bits     Mono12
//   Y12P ('Y12P')          3 per 2 pixels (MIPI RAW12)       Mono12
//   Y10  ('Y10 ')          2, little-endian, 10 low bits     Mono10
//   Y10P ('Y10P')          5 per 4 pixels (MIPI RAW10)       Mono10
//   Y10BPACK ('Y10B')      5 per 4 pixels (big-endian bits)  Mono10
//   GREY ('GREY')          1                                 Mono8
//   RGB24 ('RGB3')         3 (R, G, B)                       RGB8
//   YUYV ('YUYV')          4 per 2 pixels (Y0 U Y1 V)        RGB8 (BT.601, limited range), or
//                                                            Mono8 from Y alone
//
// A "layout" adds the size and the driver's bytesperline (rows may be padded beyond the pixels).
// Reference: Linux Media Infrastructure userspace API, "Image Formats" (pixfmt-yuv-luma.rst,
// pixfmt-rgb.rst, pixfmt-packed-yuv.rst).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frames/raw_frame.h"

namespace vem::cameras {

// Newer than some kernels' headers (Linux 6.? adds it); the value is the kernel's.
inline constexpr std::uint32_t kV4l2PixFmtY12P = std::uint32_t('Y') | (std::uint32_t('1') << 8) |
                                                 (std::uint32_t('2') << 16) |
                                                 (std::uint32_t('P') << 24);

// "Y16", "Y16-BE", "YUYV", "MJPG": the four characters without trailing spaces, "-BE" for the
// big-endian flag.
[[nodiscard]] std::string fourccName(std::uint32_t fourcc);

// The pipeline format `fourcc` gives when `requested` (a calib format name, "" = the native one)
// is asked for, or nullopt when the backend cannot read it that way.
[[nodiscard]] std::optional<PixelFormat> outputFormatOf(std::uint32_t fourcc,
                                                        std::string_view requested);

// Native formats that can give `requested`, best first ("" = every readable format, deepest
// first). Empty when `requested` names no calib format.
[[nodiscard]] std::vector<std::uint32_t> nativeCandidates(std::string_view requested);

// The first of nativeCandidates(requested) the device offers, or nullopt.
[[nodiscard]] std::optional<std::uint32_t> chooseNativeFormat(
    const std::vector<std::uint32_t>& offered, std::string_view requested);

// Bytes the pixels of one row of `widthPx` take (without padding); 0 for an unreadable format.
[[nodiscard]] std::size_t packedRowBytes(std::uint32_t fourcc, int widthPx);

struct V4l2Layout {
  std::uint32_t fourcc = 0;
  int widthPx = 0;
  int heightPx = 0;
  std::size_t bytesPerLine = 0;  // >= packedRowBytes(fourcc, widthPx)
  PixelFormat output;            // outputFormatOf(fourcc, the request)

  // The fewest bytes a buffer must hold: every row's pixels (the last row's padding may be cut).
  [[nodiscard]] std::size_t minimumBytes() const;
};

}  // namespace vem::cameras
