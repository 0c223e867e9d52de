// ShadingPoint: what a primary ray sees, ready to shade (render/shading_model.h conventions): the
// hit, the shading normal turned toward the eye (two-sided surfaces), wo toward the eye, and the
// hit's material. World frame of scene/scene.h; vectors unit.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "client/embree/embree_scene.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"

namespace vem::embree {

struct ShadingPoint {
  SurfaceHit hit;
  glm::vec3 normal{0.0F, 1.0F, 0.0F};         // shading normal, n . wo >= 0
  glm::vec3 wo{0.0F, 1.0F, 0.0F};             // -ray direction
  const scene::Material* material = nullptr;  // borrowed from the EmbreeScene
};

// The closest hit of `ray`, or nothing when it leaves the scene.
[[nodiscard]] std::optional<ShadingPoint> shadingPointOf(const EmbreeScene& scene,
                                                         const scene::Ray& ray);

// Whether nothing blocks the direction dirWorld (unit) from the point: an occlusion ray from the
// offset origin (embree_scene.h) to infinity.
[[nodiscard]] bool visibleToward(const EmbreeScene& scene, const ShadingPoint& point,
                                 glm::vec3 dirWorld);

}  // namespace vem::embree
