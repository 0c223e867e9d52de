// Map codecs (internal to vem_mapio): what the format readers and writers share. A reader turns a
// file into an RgbImage; loadMap() checks its size and gives it a layout.
//
// Conventions: RgbImage is row-major linear R, G, B floats, row 0 at the top of the picture; values
// are never clamped or cleaned. Messages are one sentence that starts with the file's path.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mapio/map_file.h"

namespace vem::mapio::detail {

enum class MapFormat { Exr, RadianceHdr, Pfm };

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // width * height * 3
};

// "<path>: <what>" as a failure.
[[nodiscard]] MapFileFailure fileFailure(MapFileError cause, const std::filesystem::path& path,
                                         std::string_view what);

// A failure unless 1 <= width <= kMaxMapWidth and 1 <= height <= kMaxMapHeight; `subject` names
// what has that size ("the map", "the OpenEXR data window").
[[nodiscard]] std::expected<void, MapFileFailure> checkMapSize(const std::filesystem::path& path,
                                                               std::string_view subject,
                                                               std::int64_t width,
                                                               std::int64_t height);

}  // namespace vem::mapio::detail
