// Scene: what vemview draws, as both renderers (OpenGL in client/gl, Embree in client/embree) see
// it: triangle meshes with one material each, in one world frame.
//
// Conventions:
// - World frame of core/env_map.h: right-handed, +Y up, lengths in scene units (metres for the
//   default scene). The lights' directions (core/light.h) are in this frame too.
// - Triangles are counter-clockwise seen from their front side; `normals` holds one unit shading
//   normal per position (loaders compute smooth normals when a file has none).
// - Materials (paper 004 section 4.2 distinguishes Lambertian and glossy surfaces):
//     f = diffuseAlbedo / pi + specular lobe, the lobe one of
//     Phong:  specularAlbedo (exponent + 2) / (2 pi) max(0, R . wi)^exponent   (R: wo mirrored)
//     Blinn:  specularAlbedo (exponent + 8) / (8 pi) max(0, N . H)^exponent    (H: half vector)
//     GGX:    Cook-Torrance, D = GGX with alpha = roughness^2, Smith G, Schlick F with
//             F0 = specularAlbedo
//   render/shading_model.h evaluates them; the GL shader mirrors that file.
//   A material is glossy when its lobe is not Lambertian and its specular albedo is non-zero;
//   it is mirror-like (reflects the cube map, not the lights) when glossy and sharper than
//   kMirrorExponent / kMirrorRoughness.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace vem::scene {

enum class Lobe { Lambertian, Phong, Blinn, Ggx };

[[nodiscard]] const char* lobeName(Lobe lobe);

inline constexpr float kMirrorExponent = 2000.0F;  // Phong / Blinn exponents above this
inline constexpr float kMirrorRoughness = 0.05F;   // GGX roughness below this

struct Material {
  std::string name;
  glm::vec3 diffuseAlbedo{0.8F};  // in [0, 1] per channel
  Lobe lobe = Lobe::Lambertian;
  glm::vec3 specularAlbedo{0.0F};  // in [0, 1] per channel; F0 for GGX
  float exponent = 0.0F;           // Phong / Blinn, >= 0
  float roughness = 1.0F;          // GGX, in (0, 1]

  [[nodiscard]] bool glossy() const;
  [[nodiscard]] bool mirrorLike() const;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // one per position, unit
  std::vector<std::uint32_t> indices;  // three per triangle, each < positions.size()
  std::uint32_t material = 0;          // index into Scene::materials

  [[nodiscard]] std::size_t triangleCount() const { return indices.size() / 3; }
};

struct Bounds {
  glm::vec3 min{0.0F};
  glm::vec3 max{0.0F};
  [[nodiscard]] glm::vec3 centre() const { return (min + max) * 0.5F; }
  [[nodiscard]] float radius() const;  // half the diagonal
};

struct Scene {
  std::string name;  // the file, or "default"
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
};

[[nodiscard]] Bounds sceneBounds(const Scene& scene);
// The bounds the shadow maps must cover: every mesh but the grounds, a ground being a flat mesh
// (every vertex within kConvexTolerance of the scene's radius of one triangle's plane) with every
// other mesh's vertices on its front side (its shading normal's) or on it. A ground hides no part
// of the scene from a light on its front side, and for a light behind it, it hides the whole of
// what lies within these bounds; outside them, in the light's view, nothing casts a shadow. The
// whole scene's bounds when every mesh is a ground (or there are none).
[[nodiscard]] Bounds shadowCasterBounds(const Scene& scene);
[[nodiscard]] std::size_t triangleCount(const Scene& scene);
[[nodiscard]] bool anyGlossy(const Scene& scene);
[[nodiscard]] bool anyMirrorLike(const Scene& scene);
// False only when no surface can hide a light from another surface: the scene is one closed or
// open convex mesh (every vertex on or behind every triangle's plane, to a tolerance relative to
// the scene's size), or has no triangles. Conservative: true whenever that is not proved.
[[nodiscard]] bool canCastShadows(const Scene& scene);

// The scene's contract (what loaders guarantee): indices in range and a multiple of three, finite
// positions, unit finite normals, one normal per position, materials in range and in their
// ranges. The first broken rule as one sentence, or empty.
[[nodiscard]] std::string firstContractViolation(const Scene& scene);

}  // namespace vem::scene
