// Radiance HDR (RGBE) and PFM map codec (internal to vem_mapio), through OpenCV's imgcodecs.
//
// Conventions: OpenCV hands out and takes BGR with row 0 at the top (its PFM codec turns the file's
// bottom-up rows over); this codec swaps to and from RGB. A grey PFM ("Pf") loads with R = G = B.
// RGBE keeps about 1 % precision and cannot store negatives, NaN or Inf; PFM stores floats exactly.
#pragma once

#include <expected>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mapio/map_codec.h"

namespace vem::mapio::detail {

// `format` is RadianceHdr or Pfm; `fileStart` holds the first bytes of the file, to check its
// signature and refuse an absurd size before OpenCV allocates it.
[[nodiscard]] std::expected<RgbImage, MapFileFailure> readWithOpenCv(
    const std::filesystem::path& path, MapFormat format, std::string_view fileStart);

// The file's bytes, or why they could not be made.
[[nodiscard]] std::expected<std::vector<unsigned char>, std::string> encodeWithOpenCv(
    const EnvMap& map, MapFormat format);

}  // namespace vem::mapio::detail
