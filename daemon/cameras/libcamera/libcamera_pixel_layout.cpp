#include "cameras/libcamera/libcamera_pixel_layout.h"

#include <cstring>

#include <fmt/format.h>

namespace vem::cameras {

namespace {

enum class Layout { Mono8, Mono16Le, Bgr8, Rgb8 };

struct Taken {
  LibcameraPixelFormat format;
  PixelFormat pixel;
  Layout layout;
};

const std::vector<Taken>& takenTable() {
  static const std::vector<Taken> table = {
      {kLibcameraR16, {1, 16}, Layout::Mono16Le}, {kLibcameraR12, {1, 12}, Layout::Mono16Le},
      {kLibcameraR10, {1, 10}, Layout::Mono16Le}, {kLibcameraRGB888, {3, 8}, Layout::Bgr8},
      {kLibcameraBGR888, {3, 8}, Layout::Rgb8},   {kLibcameraR8, {1, 8}, Layout::Mono8},
  };
  return table;
}

const Taken* findTaken(const LibcameraPixelFormat& format) {
  for (const Taken& t : takenTable()) {
    if (t.format == format) return &t;
  }
  return nullptr;
}

std::uint32_t unpackRows(const Taken& taken, LibcameraSize size, int strideBytes,
                         const std::uint8_t* bytes, std::uint16_t* codes) {
  std::uint32_t seen = 0;  // OR of every code: its high bits tell a code above the format's largest
  const int w = size.widthPx;
  for (int v = 0; v < size.heightPx; ++v) {
    const std::uint8_t* row = bytes + std::size_t(v) * std::size_t(strideBytes);
    switch (taken.layout) {
      case Layout::Mono8:
        for (int u = 0; u < w; ++u) codes[u] = row[u];
        codes += w;
        break;
      case Layout::Mono16Le:
        for (int u = 0; u < w; ++u) {
          const std::uint16_t code = std::uint16_t(row[2 * u] | (row[2 * u + 1] << 8));
          codes[u] = code;
          seen |= code;
        }
        codes += w;
        break;
      case Layout::Bgr8:
        for (int u = 0; u < w; ++u) {
          codes[3 * u + 0] = row[3 * u + 2];
          codes[3 * u + 1] = row[3 * u + 1];
          codes[3 * u + 2] = row[3 * u + 0];
        }
        codes += 3 * w;
        break;
      case Layout::Rgb8:
        for (int u = 0; u < 3 * w; ++u) codes[u] = row[u];
        codes += 3 * w;
        break;
    }
  }
  return seen;
}

}  // namespace

std::optional<PixelFormat> calibFormatOf(const LibcameraPixelFormat& format) {
  const Taken* t = findTaken(format);
  if (!t) return std::nullopt;
  return t->pixel;
}

int libcameraBytesPerPixel(const LibcameraPixelFormat& format) {
  const Taken* t = findTaken(format);
  if (!t) return 0;
  switch (t->layout) {
    case Layout::Mono8: return 1;
    case Layout::Mono16Le: return 2;
    case Layout::Bgr8:
    case Layout::Rgb8: return 3;
  }
  return 0;
}

const std::vector<LibcameraPixelFormat>& libcameraTakenFormats() {
  static const std::vector<LibcameraPixelFormat> formats = [] {
    std::vector<LibcameraPixelFormat> out;
    for (const Taken& t : takenTable()) out.push_back(t.format);
    return out;
  }();
  return formats;
}

std::optional<std::string> unpackLibcameraFrame(const LibcameraPixelFormat& format,
                                                LibcameraSize size, int strideBytes,
                                                std::span<const std::uint8_t> bytes,
                                                RawFrame& frame) {
  const Taken* taken = findTaken(format);
  if (!taken)
    return fmt::format("vemd does not take the pixel format {}", libcameraFormatName(format));
  const std::size_t rowBytes =
      std::size_t(size.widthPx) * std::size_t(libcameraBytesPerPixel(format));
  if (size.widthPx <= 0 || size.heightPx <= 0 || std::size_t(strideBytes) < rowBytes) {
    return fmt::format("the frame's geometry ({}x{}, stride {} bytes) does not hold {} pixels",
                       size.widthPx, size.heightPx, strideBytes, libcameraFormatName(format));
  }
  const std::size_t needed = std::size_t(strideBytes) * std::size_t(size.heightPx - 1) + rowBytes;
  if (bytes.size() < needed) {
    return fmt::format("the frame holds {} bytes where {}x{} {} with a stride of {} needs {}",
                       bytes.size(), size.widthPx, size.heightPx, libcameraFormatName(format),
                       strideBytes, needed);
  }
  frame.width = size.widthPx;
  frame.height = size.heightPx;
  frame.format = taken->pixel;
  frame.codes.resize(std::size_t(size.widthPx) * std::size_t(size.heightPx) *
                     std::size_t(taken->pixel.channels));
  const std::uint32_t seen =
      unpackRows(*taken, size, strideBytes, bytes.data(), frame.codes.data());
  if ((seen & ~taken->pixel.maxCode()) != 0) {
    return fmt::format("a {} frame holds codes above {}, the format's largest",
                       libcameraFormatName(format), taken->pixel.maxCode());
  }
  return std::nullopt;
}

}  // namespace vem::cameras
