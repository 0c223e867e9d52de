// DifferentialRenderer: the layers of a differential composite (render/differential_composite.h)
// by the Embree renderer: the local scene with and without the synthetic objects, from the plate
// camera, under the same lights, shading options and shadows (light_renderer.h), and each pixel's
// nearest surface in the render with the objects (its primary ray, as the renders cast it).
//
// The render without the objects depends only on the lights, the cube map, the camera and the
// size: it is kept and reused while the caller's key for those is unchanged (the render plan's
// rule: no new "without" image while the lights and the local scene are unchanged).
#pragma once

#include <cstdint>
#include <expected>
#include <optional>
#include <string>
#include <vector>

#include "client/embree/embree_scene.h"
#include "client/embree/light_renderer.h"
#include "client/render/differential_composite.h"
#include "client/scene/local_scene.h"

namespace vem::embree {

struct DifferentialTiming {
  double withObjectsMs = 0.0;
  double withoutObjectsMs = 0.0;  // 0 when reused
  double classesMs = 0.0;
  bool reusedWithout = false;
};

class DifferentialRenderer {
 public:
  // Fails (one sentence) when either scene cannot be built.
  [[nodiscard]] static std::expected<DifferentialRenderer, std::string> build(
      const scene::LocalComposition& composition);

  // `withoutKey` names the lights, cube map and camera of this frame (any hash of them); the
  // render without the objects is redone only when it, or the size, changes. With `differential`
  // false there is none (withoutObjects stays empty): the objects are only drawn over the plate.
  [[nodiscard]] render::DifferentialLayers render(
      const scene::ViewCamera& camera, int widthPx, int heightPx,
      const render::ShadingLights& lights, const render::LightingGeometry& geometry,
      const CubeMap* cube, const LightRenderOptions& options, std::uint64_t withoutKey,
      DifferentialTiming* timing = nullptr, bool differential = true);

  [[nodiscard]] const EmbreeScene& withObjects() const { return withObjects_; }
  [[nodiscard]] const EmbreeScene& localOnly() const { return localOnly_; }

 private:
  DifferentialRenderer(EmbreeScene withObjects, EmbreeScene localOnly,
                       std::vector<bool> objectMeshes);

  EmbreeScene withObjects_;
  EmbreeScene localOnly_;
  std::vector<bool> objectMeshes_;
  std::optional<std::uint64_t> withoutKey_;
  render::LinearImage without_;
};

// Each pixel's nearest surface along the primary ray through its centre: an object's, a local
// mesh's, or none.
[[nodiscard]] std::vector<render::SurfaceClass> surfaceClasses(
    const EmbreeScene& scene, const std::vector<bool>& objectMeshes,
    const scene::ViewCamera& camera, int widthPx, int heightPx, int threadCount);

}  // namespace vem::embree
