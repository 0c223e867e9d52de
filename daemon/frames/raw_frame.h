// RawFrame: one frame as the sensor delivers it, before any calibration: integer codes per pixel
// and channel, with the exposure and gain it was taken with.
//
// Conventions:
// - Pixel (u, v): u counts columns left to right, v rows top to bottom, as the sensor reads out.
//   Continuous sensor coordinates put pixel (u, v)'s centre at (u, v) (OpenCV's convention), so the
//   sensor spans [-0.5, width - 0.5] x [-0.5, height - 0.5].
// - codes: row-major, `channels` interleaved values per pixel (R, G, B for colour), each in
//   [0, 2^bits - 1] whatever the storage (Mono8 codes are stored widened in uint16).
// - exposureUs is the integration time in microseconds; gain is a linear factor (1 = unity).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vem {

// The sensor's pixel format: 1 (mono) or 3 (RGB) channels of 8 to 16 bits.
struct PixelFormat {
  int channels = 1;
  int bits = 16;

  [[nodiscard]] std::uint32_t maxCode() const { return (1u << bits) - 1u; }
  friend bool operator==(const PixelFormat&, const PixelFormat&) = default;
};

// "Mono8", "Mono10", "Mono12", "Mono16", "RGB8", "RGB10", "RGB12", "RGB16".
[[nodiscard]] std::string pixelFormatName(PixelFormat format);
[[nodiscard]] std::optional<PixelFormat> parsePixelFormat(std::string_view name);

struct RawFrame {
  int width = 0;
  int height = 0;
  PixelFormat format;
  double exposureUs = 1000.0;
  double gain = 1.0;
  std::vector<std::uint16_t> codes;  // width * height * format.channels

  [[nodiscard]] static RawFrame blank(int width, int height, PixelFormat format);
  [[nodiscard]] std::size_t index(int u, int v, int channel = 0) const {
    return (std::size_t(v) * std::size_t(width) + std::size_t(u)) * std::size_t(format.channels) +
           std::size_t(channel);
  }
  [[nodiscard]] std::uint16_t at(int u, int v, int channel = 0) const {
    return codes[index(u, v, channel)];
  }
};

}  // namespace vem
