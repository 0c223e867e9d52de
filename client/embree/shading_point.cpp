#include "client/embree/shading_point.h"

#include <glm/glm.hpp>

namespace vem::embree {

std::optional<ShadingPoint> shadingPointOf(const EmbreeScene& scene, const scene::Ray& ray) {
  const std::optional<SurfaceHit> hit = scene.intersect(ray);
  if (!hit) {
    return std::nullopt;
  }
  ShadingPoint point;
  point.hit = *hit;
  point.wo = -ray.dirWorld;
  point.normal =
      glm::dot(hit->shadingNormal, point.wo) < 0.0F ? -hit->shadingNormal : hit->shadingNormal;
  point.material = &scene.materialOf(*hit);
  return point;
}

bool visibleToward(const EmbreeScene& scene, const ShadingPoint& point, glm::vec3 dirWorld) {
  const glm::vec3 origin = offsetOrigin(point.hit, dirWorld, scene.offsetEpsilon());
  return !scene.occluded(origin, dirWorld);
}

}  // namespace vem::embree
