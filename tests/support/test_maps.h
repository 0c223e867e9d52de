// Maps for the core's tests: constant, single hot pixel, procedural skies, and the shared HDRIs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/env_map.h"

namespace vem::testing {

// A smooth, strictly positive sky-and-ground map with a warm bright region: no file needed.
[[nodiscard]] EnvMap proceduralSky(MapLayout layout, int width, int height);
// `background` everywhere and one pixel (x, y) of `hot`.
[[nodiscard]] EnvMap hotPixelMap(MapLayout layout, int width, int height, int x, int y, float hot,
                                 float background);
// The map rotated about +Y by `columns` whole pixels (column x moves to x + columns).
[[nodiscard]] EnvMap rotatedColumns(const EnvMap& map, int columns);

// The shared HDRIs (VEM_SHARED_DATA_DIR/hdri/*.exr), sorted; empty when the folder is absent.
[[nodiscard]] std::vector<std::filesystem::path> sharedHdriPaths();

}  // namespace vem::testing
