#include "client/vemview/prefiltered_environment.h"

#include <chrono>

namespace vem::view {

PrefilteredEnvironment::PrefilteredEnvironment(const RenderPlan& plan) {
  if (!plan.shadingByRatio) return;
  options_ = render::EnvironmentLightingOptions{};
  options_->diffuse = plan.irradianceCube;
  options_->specular = plan.glossyEnvironment;
  options_->peakFactor = render::peakFactorFor(plan.lighting.lightCount);
}

PrefilteredEnvironment::Current PrefilteredEnvironment::forCube(
    const std::shared_ptr<const CubeMap>& cube, std::span<const scene::Material> materials) {
  if (!options_ || cube == nullptr) return {};
  Current out;
  if (cube != cube_) {
    const auto start = std::chrono::steady_clock::now();
    lighting_ = render::makeEnvironmentLighting(*cube, materials, *options_);
    cube_ = cube;
    ++version_;
    out.builtMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
  }
  out.lighting = &lighting_;
  out.version = version_;
  return out;
}

}  // namespace vem::view
