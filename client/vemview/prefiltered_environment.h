// PrefilteredEnvironment: the render::EnvironmentLighting of the frames' cube map for shading by
// ratio (issue 20), shared by the OpenGL and Embree frame renderers. Built only when the cube map
// changes (inputs hand out the same shared cube until a new one arrives) and only with the parts
// the render plan asks for (no irradiance cube without a diffuse material, no clipped environment
// for the glossy lobes without a glossy one).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "client/render/environment_lighting.h"
#include "client/scene/scene.h"
#include "client/vemview/render_plan.h"
#include "core/cube_map.h"

namespace vem::view {

class PrefilteredEnvironment {
 public:
  explicit PrefilteredEnvironment(const RenderPlan& plan);

  struct Current {
    const render::EnvironmentLighting* lighting = nullptr;  // null: shade by the lights
    std::uint64_t version = 0;     // changes whenever `lighting` was rebuilt
    std::optional<double> builtMs;  // set on the frame that rebuilt it
  };
  // Null lighting without ratio shading or a cube map.
  [[nodiscard]] Current forCube(const std::shared_ptr<const CubeMap>& cube,
                                std::span<const scene::Material> materials);

 private:
  std::optional<render::EnvironmentLightingOptions> options_;
  std::shared_ptr<const CubeMap> cube_;
  render::EnvironmentLighting lighting_;
  std::uint64_t version_ = 0;
};

}  // namespace vem::view
