// The native GenICam pixel formats the Aravis backend reads, and their conversion into RawFrame
// codes (daemon/frames/raw_frame.h: row-major, channels interleaved, widened to uint16). Pure.
//
// Layouts (GenICam PFNC 2.4 and GigE Vision 2.x), pixels in readout order, rows unpadded:
// - Mono8: one byte per pixel. RGB8 (GigE Vision 1.x calls it RGB8Packed; same code 0x02180014):
//   R, G, B bytes per pixel.
// - Mono10, Mono12, Mono16: one little-endian 16-bit word per pixel, the value in the low bits.
// - Mono10Packed, Mono12Packed (GigE Vision): two pixels in three bytes; byte 0 holds pixel 0's
//   high 8 bits, byte 2 pixel 1's; byte 1 holds their low bits (pixel 0's in bits 0.., pixel 1's
//   in bits 4..).
// - Mono10p, Mono12p (PFNC): one little-endian bit stream, pixel i in bits [i*n, i*n + n).
// Anything else (Bayer, YUV, Mono14, RGB16...) is refused with a sentence.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frames/raw_frame.h"

namespace vem::cameras {

enum class PixelLayout { Bytes8, Words16, GvPacked, PfncPacked };

struct NativePixelFormat {
  std::string_view genicamName;  // the PixelFormat enumeration entry: "Mono12Packed"
  std::uint32_t code = 0;        // PFNC / GigE Vision code, as buffers carry it
  PixelFormat format;            // what the pipeline receives
  PixelLayout layout = PixelLayout::Bytes8;
  int bitsPerPixel = 8;  // on the wire, all channels
};

// Every format read, deepest first (the order "" picks in), unpacked before packed variants.
[[nodiscard]] std::span<const NativePixelFormat> nativePixelFormats();
[[nodiscard]] const NativePixelFormat* nativeFormatByName(std::string_view genicamName);
[[nodiscard]] const NativePixelFormat* nativeFormatByCode(std::uint32_t code);

// Bytes one width x height frame takes on the wire.
[[nodiscard]] std::size_t payloadBytes(const NativePixelFormat& native, int widthPx, int heightPx);

// The native format to set for `wanted` (calib's name, "" = the deepest offered), among the
// PixelFormat entries the camera offers; or one sentence naming what is missing.
[[nodiscard]] std::expected<const NativePixelFormat*, std::string> chooseNativeFormat(
    std::string_view wanted, const std::vector<std::string>& offered);

// Decodes `data` (at least payloadBytes) into `codes` (resized to width * height * channels,
// its storage reused). False when data is too short.
[[nodiscard]] bool decodePixels(const NativePixelFormat& native, std::span<const std::uint8_t> data,
                                int widthPx, int heightPx, std::vector<std::uint16_t>& codes);

}  // namespace vem::cameras
