#include "frames/raw_frame.h"

#include <charconv>

namespace vem {

std::string pixelFormatName(PixelFormat format) {
  return (format.channels == 1 ? "Mono" : "RGB") + std::to_string(format.bits);
}

std::optional<PixelFormat> parsePixelFormat(std::string_view name) {
  PixelFormat format;
  std::string_view digits;
  if (name.starts_with("Mono")) {
    format.channels = 1;
    digits = name.substr(4);
  } else if (name.starts_with("RGB")) {
    format.channels = 3;
    digits = name.substr(3);
  } else {
    return std::nullopt;
  }
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), format.bits);
  if (ec != std::errc{} || end != digits.data() + digits.size()) return std::nullopt;
  if (format.bits != 8 && format.bits != 10 && format.bits != 12 && format.bits != 16) {
    return std::nullopt;
  }
  return format;
}

RawFrame RawFrame::blank(int width, int height, PixelFormat format) {
  RawFrame frame;
  frame.width = width;
  frame.height = height;
  frame.format = format;
  frame.codes.assign(std::size_t(width) * std::size_t(height) * std::size_t(format.channels), 0);
  return frame;
}

}  // namespace vem
