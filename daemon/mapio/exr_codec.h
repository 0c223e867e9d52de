// OpenEXR map codec (internal to vem_mapio), through the OpenEXR library.
//
// Conventions:
// - Reads scanline or tiled files with half, float or uint channels R, G, B, or a lone luminance Y
//   (loaded grey). Luminance-chroma (RY, BY) files and subsampled channels are refused.
// - The map is the file's display window, row 0 at its top (min.y). Display pixels outside the data
//   window are 0, OpenEXR's "no data"; data outside the display window is dropped.
// - Writes 32-bit float R, G, B with ZIP compression, display window = data window at the origin.
#pragma once

#include <expected>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mapio/map_codec.h"

namespace vem::mapio::detail {

// `fileStart` holds the first bytes of the file, to check its signature.
[[nodiscard]] std::expected<RgbImage, MapFileFailure> readExr(const std::filesystem::path& path,
                                                              std::string_view fileStart);

// The file's bytes, or why they could not be made.
[[nodiscard]] std::expected<std::vector<unsigned char>, std::string> encodeExr(const EnvMap& map);

}  // namespace vem::mapio::detail
