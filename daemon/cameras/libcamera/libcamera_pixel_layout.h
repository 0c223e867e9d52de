// How libcamera's pixel formats lay out a frame in memory, and how vemd widens them into RawFrame
// codes (daemon/frames/raw_frame.h). Pure: no libcamera calls.
//
// Formats vemd takes (libcamera's names; DRM fourccs, linear: modifier 0):
//   R8     'R8  '  one byte per pixel                                   -> Mono8
//   R10    'R10 '  little-endian 16-bit words, code in bits 0..9         -> Mono10
//   R12    'R12 '  little-endian 16-bit words, code in bits 0..11        -> Mono12
//   R16    'R16 '  little-endian 16-bit words                            -> Mono16
//   RGB888 'RG24'  three bytes per pixel, in memory B, G, R (DRM_FORMAT_RGB888 is [23:0] R:G:B
//                  little-endian)                                        -> RGB8
//   BGR888 'BG24'  three bytes per pixel, in memory R, G, B              -> RGB8
// libcamera 0.0.3's formats.h defines R8, R10, R12 (and the packed R10_CSI2P) but not R16: vemd
// names R16 by its DRM fourcc, as later libcamera versions do (formats::R16). Packed CSI-2 formats
// (a non-zero modifier), Bayer, YUV and compressed formats are refused.
//
// Rows are strideBytes apart (stride >= width * bytes per pixel; the padding is skipped).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cameras/libcamera/libcamera_port.h"
#include "frames/raw_frame.h"

namespace vem::cameras {

[[nodiscard]] constexpr std::uint32_t drmFourcc(char a, char b, char c, char d) {
  return std::uint32_t(std::uint8_t(a)) | (std::uint32_t(std::uint8_t(b)) << 8) |
         (std::uint32_t(std::uint8_t(c)) << 16) | (std::uint32_t(std::uint8_t(d)) << 24);
}

inline constexpr LibcameraPixelFormat kLibcameraR8{drmFourcc('R', '8', ' ', ' '), 0};
inline constexpr LibcameraPixelFormat kLibcameraR10{drmFourcc('R', '1', '0', ' '), 0};
inline constexpr LibcameraPixelFormat kLibcameraR12{drmFourcc('R', '1', '2', ' '), 0};
inline constexpr LibcameraPixelFormat kLibcameraR16{drmFourcc('R', '1', '6', ' '), 0};
inline constexpr LibcameraPixelFormat kLibcameraRGB888{drmFourcc('R', 'G', '2', '4'), 0};
inline constexpr LibcameraPixelFormat kLibcameraBGR888{drmFourcc('B', 'G', '2', '4'), 0};

// The RawFrame format a libcamera format gives, or nullopt when vemd does not take it.
[[nodiscard]] std::optional<PixelFormat> calibFormatOf(const LibcameraPixelFormat& format);
// Bytes one pixel takes in memory (taken formats only).
[[nodiscard]] int libcameraBytesPerPixel(const LibcameraPixelFormat& format);
// The formats vemd takes, deepest first ("" in CameraSettings::pixelFormat picks the first
// offered).
[[nodiscard]] const std::vector<LibcameraPixelFormat>& libcameraTakenFormats();

// Widens a frame of `format` and `size` stored in `bytes` (rows strideBytes apart) into
// frame.codes, reusing its storage, and sets width, height and format. Returns why it cannot
// (too few bytes, a code above the format's largest), or nullopt.
[[nodiscard]] std::optional<std::string> unpackLibcameraFrame(const LibcameraPixelFormat& format,
                                                              LibcameraSize size, int strideBytes,
                                                              std::span<const std::uint8_t> bytes,
                                                              RawFrame& frame);

}  // namespace vem::cameras
