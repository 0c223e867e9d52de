#include "client/vemview/simulated_plate.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "client/embree/embree_scene.h"
#include "client/embree/reference_renderer.h"

namespace vem::view {

std::expected<std::unique_ptr<PlateSource>, std::string> openSimulatedPlate(
    const scene::MixedRealityWorld& world, const EnvMap& map, int widthPx, int heightPx,
    double relativeError) {
  auto scene = embree::EmbreeScene::build(world.realSurfaces);
  if (!scene) return std::unexpected("the simulated plate: " + scene.error());
  const auto start = std::chrono::steady_clock::now();
  embree::ReferenceOptions options;
  options.targetRelativeError = relativeError;
  options.threadCount = 0;
  embree::ReferenceResult result = embree::renderReference(*scene, scene::plateViewCamera(world),
                                                           widthPx, heightPx, map, options);
  std::ranges::fill(result.image.covered, std::uint8_t{1});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stillPlate(
      fmt::format("sim: {} by its plate camera ({} x {}, Monte Carlo to {:.1f} %, {:.1f} s)",
                  world.realSurfaces.name, widthPx, heightPx, 100.0 * result.relativeError,
                  seconds),
      PlateFrame{std::move(result.image), false, 0.0, false, 1});
}

}  // namespace vem::view
