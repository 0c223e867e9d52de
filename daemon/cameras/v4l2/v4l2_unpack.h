// Unpacking one V4L2 buffer into a RawFrame (daemon/frames/raw_frame.h): every native format of
// v4l2_formats.h, rows read at the driver's bytesperline (padding skipped). Pure.
//
// - 16-bit containers (Y16, Y12, Y10): little-endian (Y16-BE: big-endian); Y12 and Y10 keep their
//   12 or 10 low bits (the spec leaves the high bits 0).
// - Y10P / Y12P (MIPI RAW10 / RAW12): each group of 4 (2) pixels is their high 8 bits, one byte
//   each, then one byte of their low bits, the first pixel's in the lowest bits.
// - Y10BPACK: a big-endian bit stream, 10 bits per pixel, most significant bit first.
// - YUYV -> RGB8: ITU-R BT.601, limited range (Y 16..235, Cb/Cr 16..240), the usual integer form
//   R = (298 (Y-16) + 409 (Cr-128) + 128) >> 8, G = (298 (Y-16) - 100 (Cb-128) - 208 (Cr-128) +
//   128) >> 8, B = (298 (Y-16) + 516 (Cb-128) + 128) >> 8, clipped to 0..255; each pair of pixels
//   shares Cb and Cr. YUYV -> Mono8 takes Y as is.
// Reference: Linux Media Infrastructure userspace API, "Image Formats".
#pragma once

#include <cstddef>
#include <span>

#include "cameras/v4l2/v4l2_formats.h"
#include "frames/raw_frame.h"

namespace vem::cameras {

// Reads `data` (at least layout.minimumBytes() bytes) into `frame`: size, format and codes set,
// the codes' storage reused; exposure and gain untouched.
void unpackV4l2Frame(std::span<const std::byte> data, const V4l2Layout& layout, RawFrame& frame);

}  // namespace vem::cameras
