// EmbreeScene: a scene::Scene as an Embree 3 BVH (one triangle geometry per mesh, geometry id =
// mesh index) with the two queries the CPU renderers need: the closest hit of a ray and whether a
// segment is blocked.
//
// Conventions:
// - World frame and units of scene/scene.h. Ray directions unit; distances t in scene units along
//   the ray, searched in [tNear, tFar].
// - A hit's geometricNormal is the unit normal of the triangle's front side (counter-clockwise
//   winding: normalize((p1 - p0) x (p2 - p0))); shadingNormal is the vertex normals interpolated
//   with Embree's barycentrics (p = (1 - u - v) p0 + u p1 + v p2) and normalised (the geometric
//   normal where they cancel). Neither is turned toward the ray: callers make surfaces two-sided.
// - offsetEpsilon() is the distance secondary rays start off a surface: kRelativeEpsilon times the
//   scene's bounding radius (at least kRelativeEpsilon scene units).
// Owns its Embree device and scene (RAII, move-only) and a copy of the meshes' normals and indices.
// Queries are const and thread-safe (the BVH is committed once in build()).
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace vem::embree {

inline constexpr float kRelativeEpsilon = 1e-4F;

struct SurfaceHit {
  float distance = 0.0F;  // t along the ray
  glm::vec3 positionWorld{0.0F};
  glm::vec3 geometricNormal{0.0F, 1.0F, 0.0F};  // unit, front side
  glm::vec3 shadingNormal{0.0F, 1.0F, 0.0F};    // unit, interpolated
  std::uint32_t meshIndex = 0;
  std::uint32_t materialIndex = 0;
};

class EmbreeScene {
 public:
  // Builds the BVH. Fails (one sentence) when the scene breaks its contract
  // (scene::firstContractViolation) or Embree reports an error. `deviceConfig` goes to
  // rtcNewDevice (e.g. "threads=1").
  [[nodiscard]] static std::expected<EmbreeScene, std::string> build(
      const scene::Scene& scene, const std::string& deviceConfig = "");

  [[nodiscard]] std::optional<SurfaceHit> intersect(const scene::Ray& ray, float tNear = 0.0F,
                                                    float tFar = kInfinity) const;
  // True when any triangle lies on the ray within (tNear, tFar).
  [[nodiscard]] bool occluded(glm::vec3 originWorld, glm::vec3 dirWorld, float tNear = 0.0F,
                              float tFar = kInfinity) const;

  [[nodiscard]] const std::vector<scene::Material>& materials() const { return materials_; }
  [[nodiscard]] const scene::Material& materialOf(const SurfaceHit& hit) const {
    return materials_[hit.materialIndex];
  }
  [[nodiscard]] float offsetEpsilon() const { return epsilon_; }

  static constexpr float kInfinity = 3.0e38F;

 private:
  struct DeviceRelease {
    void operator()(RTCDeviceTy* device) const;
  };
  struct SceneRelease {
    void operator()(RTCSceneTy* scene) const;
  };
  struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    std::uint32_t material = 0;
  };

  EmbreeScene() = default;
  [[nodiscard]] SurfaceHit surfaceHit(std::uint32_t geomId, std::uint32_t primId, float u, float v,
                                      const scene::Ray& ray, float t) const;

  std::unique_ptr<RTCDeviceTy, DeviceRelease> device_;
  std::unique_ptr<RTCSceneTy, SceneRelease> scene_;
  std::vector<MeshData> meshes_;
  std::vector<scene::Material> materials_;
  float epsilon_ = kRelativeEpsilon;
};

// The point a secondary ray toward dirWorld starts from: off the surface along the geometric
// normal, on the side dirWorld leaves toward.
[[nodiscard]] glm::vec3 offsetOrigin(const SurfaceHit& hit, glm::vec3 dirWorld, float epsilon);

}  // namespace vem::embree
