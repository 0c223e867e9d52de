// Map files: loading and saving an EnvMap as .exr (OpenEXR), .hdr (Radiance RGBE) or .pfm (Portable
// Float Map). docs/map-files.md describes the formats and lists the error messages.
//
// Conventions:
// - The format follows the file's extension, compared case-insensitively.
// - Pixels are linear RGB floats, row 0 at the top of the picture (the zenith), red first, whatever
// the
//   file's own storage order (PFM stores rows bottom-up; OpenCV hands out BGR; EXR sorts B, G, R).
//   A grey file (EXR luminance Y, PFM "Pf") loads with R = G = B.
// - Values pass through unchanged both ways: NaN, Inf and negatives are kept (RGBE cannot store
// them).
// - The layout is the caller's, or else follows the aspect ratio (defaultLayout below).
// - Failures are values: every library exception is caught, and a failed save leaves any existing
//   file at the path untouched (the map is written beside it and renamed over it).
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <string>

#include "core/env_map.h"

namespace vem::mapio {

enum class MapFileError { NotFound, Unreadable, UnsupportedFormat, BadContents, WriteFailed };

[[nodiscard]] const char* mapFileErrorName(MapFileError error);

struct MapFileFailure {
  MapFileError cause;
  std::string message;  // one sentence naming the file and what was expected
};

// Largest map accepted on load, in pixels: kMaxMapWidth x kMaxMapHeight.
inline constexpr int kMaxMapWidth = 16384;
inline constexpr int kMaxMapHeight = 8192;

// Layout of a map with no explicit layout: W = 2 H is an equirectangular Sphere, W = 4 H the
// camera's polar Hemisphere map (360 x 90); any other shape has none.
[[nodiscard]] std::optional<MapLayout> defaultLayout(int width, int height);

// Reads the map at `path`; `layout` overrides defaultLayout().
[[nodiscard]] std::expected<EnvMap, MapFileFailure> loadMap(const std::filesystem::path& path,
                                                            std::optional<MapLayout> layout = {});

// Writes `map` to `path` atomically (.exr as 32-bit float R, G, B with ZIP compression).
[[nodiscard]] std::expected<void, MapFileFailure> saveMap(const EnvMap& map,
                                                          const std::filesystem::path& path);

}  // namespace vem::mapio
