// Each pixel's nearest surface for a differential composite (render/differential_composite.h):
// a synthetic object's, a local mesh's (the real surfaces' stand-ins), or none, along the primary
// ray through the pixel's centre (scene::ViewCamera::primaryRay, as both renderers cast them, so
// the classes line up with the OpenGL and Embree layers alike).
#pragma once

#include <vector>

#include "client/embree/embree_scene.h"
#include "client/render/differential_composite.h"
#include "client/scene/view_camera.h"

namespace vem::embree {

// objectMeshes: per mesh of `scene`, true for a synthetic object's (scene::LocalComposition).
// Rows are shared by up to threadCount of TBB's threads (<= 0: one per hardware thread).
[[nodiscard]] std::vector<render::SurfaceClass> surfaceClasses(
    const EmbreeScene& scene, const std::vector<bool>& objectMeshes,
    const scene::ViewCamera& camera, int widthPx, int heightPx, int threadCount);

}  // namespace vem::embree
