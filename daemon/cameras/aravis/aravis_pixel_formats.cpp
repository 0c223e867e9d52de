#include "cameras/aravis/aravis_pixel_formats.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

constexpr PixelFormat kMono8{1, 8}, kMono10{1, 10}, kMono12{1, 12}, kMono16{1, 16}, kRgb8{3, 8};

constexpr std::array kFormats{
    NativePixelFormat{"Mono16", 0x01100007u, kMono16, PixelLayout::Words16, 16},
    NativePixelFormat{"Mono12", 0x01100005u, kMono12, PixelLayout::Words16, 16},
    NativePixelFormat{"Mono12p", 0x010c0047u, kMono12, PixelLayout::PfncPacked, 12},
    NativePixelFormat{"Mono12Packed", 0x010c0006u, kMono12, PixelLayout::GvPacked, 12},
    NativePixelFormat{"Mono10", 0x01100003u, kMono10, PixelLayout::Words16, 16},
    NativePixelFormat{"Mono10p", 0x010a0046u, kMono10, PixelLayout::PfncPacked, 10},
    NativePixelFormat{"Mono10Packed", 0x010c0004u, kMono10, PixelLayout::GvPacked, 12},
    NativePixelFormat{"RGB8", 0x02180014u, kRgb8, PixelLayout::Bytes8, 24},
    NativePixelFormat{"RGB8Packed", 0x02180014u, kRgb8, PixelLayout::Bytes8, 24},
    NativePixelFormat{"Mono8", 0x01080001u, kMono8, PixelLayout::Bytes8, 8},
};

void decodeBytes(std::span<const std::uint8_t> data, std::vector<std::uint16_t>& codes) {
  std::copy(data.begin(), data.begin() + std::ptrdiff_t(codes.size()), codes.begin());
}

void decodeWords(std::span<const std::uint8_t> data, std::vector<std::uint16_t>& codes) {
  for (std::size_t i = 0; i < codes.size(); ++i) {
    codes[i] = std::uint16_t(data[2 * i] | (data[2 * i + 1] << 8));
  }
}

// GigE Vision MonoNPacked: two pixels in three bytes, `bits` = 10 or 12.
void decodeGvPacked(std::span<const std::uint8_t> data, int bits,
                    std::vector<std::uint16_t>& codes) {
  const int low = bits - 8;
  const unsigned lowMask = (1u << low) - 1u;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const std::size_t group = (i / 2) * 3;
    const unsigned lowBits =
        i % 2 == 0 ? data[group + 1] & lowMask : (unsigned(data[group + 1]) >> 4) & lowMask;
    const unsigned high = data[group + (i % 2 == 0 ? 0 : 2)];
    codes[i] = std::uint16_t((high << low) | lowBits);
  }
}

// PFNC MonoNp: a little-endian bit stream, `bits` per pixel.
void decodePfncPacked(std::span<const std::uint8_t> data, int bits,
                      std::vector<std::uint16_t>& codes) {
  const std::uint32_t mask = (1u << bits) - 1u;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const std::size_t bit = i * std::size_t(bits);
    const std::size_t byte = bit / 8;
    std::uint32_t window = data[byte];
    if (byte + 1 < data.size()) window |= std::uint32_t(data[byte + 1]) << 8;
    if (byte + 2 < data.size()) window |= std::uint32_t(data[byte + 2]) << 16;
    codes[i] = std::uint16_t((window >> (bit % 8)) & mask);
  }
}

std::string joined(const std::vector<std::string>& names) {
  return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

std::span<const NativePixelFormat> nativePixelFormats() { return kFormats; }

const NativePixelFormat* nativeFormatByName(std::string_view genicamName) {
  for (const auto& f : kFormats) {
    if (f.genicamName == genicamName) return &f;
  }
  return nullptr;
}

const NativePixelFormat* nativeFormatByCode(std::uint32_t code) {
  for (const auto& f : kFormats) {
    if (f.code == code) return &f;
  }
  return nullptr;
}

std::size_t payloadBytes(const NativePixelFormat& native, int widthPx, int heightPx) {
  const std::size_t bits =
      std::size_t(widthPx) * std::size_t(heightPx) * std::size_t(native.bitsPerPixel);
  return (bits + 7) / 8;
}

std::expected<const NativePixelFormat*, std::string> chooseNativeFormat(
    std::string_view wanted, const std::vector<std::string>& offered) {
  std::optional<PixelFormat> target;
  if (!wanted.empty()) {
    target = parsePixelFormat(wanted);
    const bool known =
        target && std::ranges::any_of(kFormats, [&](const auto& f) { return f.format == *target; });
    if (!known) {
      return std::unexpected(fmt::format(
          "pixel format \"{}\" is not one the Aravis backend reads (Mono8, Mono10, Mono12, "
          "Mono16 or RGB8)",
          wanted));
    }
  }
  for (const auto& f : kFormats) {
    if (target && f.format != *target) continue;
    if (std::ranges::find(offered, f.genicamName) != offered.end()) return &f;
  }
  if (target) {
    return std::unexpected(fmt::format("the camera offers no pixel format giving {} (it offers {})",
                                       wanted, joined(offered)));
  }
  return std::unexpected(fmt::format(
      "the camera offers none of the pixel formats the Aravis backend reads (it offers {})",
      joined(offered)));
}

bool decodePixels(const NativePixelFormat& native, std::span<const std::uint8_t> data, int widthPx,
                  int heightPx, std::vector<std::uint16_t>& codes) {
  if (widthPx <= 0 || heightPx <= 0) return false;
  if (data.size() < payloadBytes(native, widthPx, heightPx)) return false;
  codes.resize(std::size_t(widthPx) * std::size_t(heightPx) * std::size_t(native.format.channels));
  switch (native.layout) {
    case PixelLayout::Bytes8: decodeBytes(data, codes); break;
    case PixelLayout::Words16: decodeWords(data, codes); break;
    case PixelLayout::GvPacked: decodeGvPacked(data, native.format.bits, codes); break;
    case PixelLayout::PfncPacked: decodePfncPacked(data, native.format.bits, codes); break;
  }
  return true;
}

}  // namespace vem::cameras
