// Image files of rendered frames: the linear frame as OpenEXR (32-bit float RGB, through
// daemon/mapio) and the tone-mapped frame as 8-bit sRGB PNG (through OpenCV). Row 0 is the top of
// the picture in both. Writes are atomic (a failed write leaves an earlier file unchanged); errors
// are one sentence naming the file.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <span>
#include <string>

#include "client/render/linear_image.h"

namespace vem::render {

[[nodiscard]] std::expected<void, std::string> saveLinearExr(const LinearImage& image,
                                                             const std::filesystem::path& path);
// srgb8: widthPx * heightPx * 3 bytes, RGB order, row 0 at the top.
[[nodiscard]] std::expected<void, std::string> saveSrgbPng(std::span<const std::uint8_t> srgb8,
                                                           int widthPx, int heightPx,
                                                           const std::filesystem::path& path);
// An 8-bit RGB PNG (or any OpenCV-readable picture) as RGB bytes, row 0 at the top.
struct Srgb8Image {
  int widthPx = 0;
  int heightPx = 0;
  std::vector<std::uint8_t> rgb;
};
[[nodiscard]] std::expected<Srgb8Image, std::string> loadSrgb8(const std::filesystem::path& path);
[[nodiscard]] std::expected<LinearImage, std::string> loadLinearExr(
    const std::filesystem::path& path);

}  // namespace vem::render
