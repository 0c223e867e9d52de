// The simulated plate (--plate sim): the simulated real world's surfaces
// (client/scene/mixed_reality_world.h) filmed by its plate camera, rendered once by the Monte
// Carlo reference (client/embree/reference_renderer.h) under the input's environment map, at
// widthPx x heightPx, to relativeError. A linear (not display-referred) still plate: mixed reality
// with no camera and nothing to download. The map must be Sphere or Hemisphere layout.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/scene/mixed_reality_world.h"
#include "client/vemview/plate_source.h"
#include "core/env_map.h"

namespace vem::view {

inline constexpr double kSimulatedPlateError = 0.05;

[[nodiscard]] std::expected<std::unique_ptr<PlateSource>, std::string> openSimulatedPlate(
    const scene::MixedRealityWorld& world, const EnvMap& map, int widthPx, int heightPx,
    double relativeError = kSimulatedPlateError);

}  // namespace vem::view
