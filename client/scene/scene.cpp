#include "client/scene/scene.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <optional>

namespace vem::scene {
namespace {

constexpr float kUnitTolerance = 1e-3F;
constexpr float kConvexTolerance = 1e-4F;              // of the scene's radius
constexpr std::size_t kMaxConvexityTriangles = 20000;  // larger meshes are assumed non-convex

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool inUnitRange(glm::vec3 v) {
  return v.x >= 0.0F && v.y >= 0.0F && v.z >= 0.0F && v.x <= 1.0F && v.y <= 1.0F && v.z <= 1.0F;
}

bool convex(const Mesh& mesh, float tolerance) {
  if (mesh.triangleCount() > kMaxConvexityTriangles) {
    return false;
  }
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
    const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    if (length == 0.0F) {
      continue;  // a degenerate triangle hides nothing
    }
    const glm::vec3 normal = cross / length;
    for (const glm::vec3& p : mesh.positions) {
      if (glm::dot(p - a, normal) > tolerance) {
        return false;
      }
    }
  }
  return true;
}

std::string materialViolation(const Material& m, std::size_t index) {
  const auto where = fmt::format("material {} ('{}')", index, m.name);
  if (!finite(m.diffuseAlbedo) || !inUnitRange(m.diffuseAlbedo)) {
    return where + ": the diffuse albedo must lie in [0, 1] per channel";
  }
  if (!finite(m.specularAlbedo) || !inUnitRange(m.specularAlbedo)) {
    return where + ": the specular albedo must lie in [0, 1] per channel";
  }
  if (!std::isfinite(m.exponent) || m.exponent < 0.0F) {
    return where + ": the specular exponent must be a finite number >= 0";
  }
  if (!std::isfinite(m.roughness) || m.roughness <= 0.0F || m.roughness > 1.0F) {
    return where + ": the roughness must lie in (0, 1]";
  }
  return {};
}

std::string meshViolation(const Mesh& mesh, std::size_t index, std::size_t materialCount) {
  const auto where = fmt::format("mesh {} ('{}')", index, mesh.name);
  if (mesh.indices.size() % 3 != 0) {
    return where + ": the index count must be a multiple of three";
  }
  if (mesh.normals.size() != mesh.positions.size()) {
    return where + ": there must be one normal per position";
  }
  if (mesh.material >= materialCount) {
    return fmt::format("{}: material {} does not exist ({} materials)", where, mesh.material,
                       materialCount);
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= mesh.positions.size()) {
      return fmt::format("{}: index {} is {}, past the {} positions", where, i, mesh.indices[i],
                         mesh.positions.size());
    }
  }
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!finite(mesh.positions[i])) {
      return fmt::format("{}: position {} is not finite", where, i);
    }
    if (!finite(mesh.normals[i]) ||
        std::abs(glm::length(mesh.normals[i]) - 1.0F) > kUnitTolerance) {
      return fmt::format("{}: normal {} is not a finite unit vector", where, i);
    }
  }
  return {};
}

}  // namespace

const char* lobeName(Lobe lobe) {
  switch (lobe) {
    case Lobe::Lambertian: return "lambertian";
    case Lobe::Phong: return "phong";
    case Lobe::Blinn: return "blinn";
    case Lobe::Ggx: return "ggx";
  }
  return "?";
}

bool Material::glossy() const {
  return lobe != Lobe::Lambertian &&
         std::max({specularAlbedo.x, specularAlbedo.y, specularAlbedo.z}) > 0.0F;
}

bool Material::mirrorLike() const {
  if (!glossy()) {
    return false;
  }
  return lobe == Lobe::Ggx ? roughness < kMirrorRoughness : exponent > kMirrorExponent;
}

float Bounds::radius() const { return 0.5F * glm::length(max - min); }

namespace {

// The plane of a flat mesh oriented by its first shading normal, or nullopt when it is not flat.
struct Plane {
  glm::vec3 normal;
  glm::vec3 point;
};
std::optional<Plane> flatPlane(const Mesh& mesh, float tolerance) {
  if (mesh.triangleCount() == 0 || mesh.normals.empty()) return std::nullopt;
  std::optional<Plane> plane;
  for (std::size_t t = 0; t < mesh.triangleCount() && !plane; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 cross = glm::cross(mesh.positions[mesh.indices[3 * t + 1]] - a,
                                       mesh.positions[mesh.indices[3 * t + 2]] - a);
    const float length = glm::length(cross);
    if (length > 0.0F) plane = Plane{cross / length, a};
  }
  if (!plane) return std::nullopt;
  if (glm::dot(plane->normal, mesh.normals.front()) < 0.0F) plane->normal = -plane->normal;
  for (const glm::vec3& p : mesh.positions) {
    if (std::abs(glm::dot(p - plane->point, plane->normal)) > tolerance) return std::nullopt;
  }
  return plane;
}

bool isGround(const Scene& scene, std::size_t index, float tolerance) {
  const std::optional<Plane> plane = flatPlane(scene.meshes[index], tolerance);
  if (!plane) return false;
  for (std::size_t other = 0; other < scene.meshes.size(); ++other) {
    if (other == index) continue;
    for (const glm::vec3& p : scene.meshes[other].positions) {
      if (glm::dot(p - plane->point, plane->normal) < -tolerance) return false;
    }
  }
  return true;
}

}  // namespace

Bounds shadowCasterBounds(const Scene& scene) {
  const Bounds whole = sceneBounds(scene);
  const float tolerance = kConvexTolerance * std::max(whole.radius(), 1e-6F);
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  bool any = false;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    if (isGround(scene, i, tolerance)) continue;
    for (const glm::vec3& p : scene.meshes[i].positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      any = true;
    }
  }
  return any ? Bounds{lo, hi} : whole;
}

Bounds sceneBounds(const Scene& scene) {
  glm::vec3 lo(std::numeric_limits<float>::max());
  glm::vec3 hi(std::numeric_limits<float>::lowest());
  bool any = false;
  for (const Mesh& mesh : scene.meshes) {
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
      any = true;
    }
  }
  return any ? Bounds{lo, hi} : Bounds{};
}

std::size_t triangleCount(const Scene& scene) {
  std::size_t count = 0;
  for (const Mesh& mesh : scene.meshes) {
    count += mesh.triangleCount();
  }
  return count;
}

bool anyGlossy(const Scene& scene) {
  return std::ranges::any_of(scene.meshes, [&](const Mesh& mesh) {
    return mesh.triangleCount() > 0 && scene.materials.at(mesh.material).glossy();
  });
}

bool anyMirrorLike(const Scene& scene) {
  return std::ranges::any_of(scene.meshes, [&](const Mesh& mesh) {
    return mesh.triangleCount() > 0 && scene.materials.at(mesh.material).mirrorLike();
  });
}

bool canCastShadows(const Scene& scene) {
  const Mesh* only = nullptr;
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.triangleCount() == 0) {
      continue;
    }
    if (only != nullptr) {
      return true;  // two meshes: one may stand between the light and the other
    }
    only = &mesh;
  }
  if (only == nullptr) {
    return false;
  }
  return !convex(*only, kConvexTolerance * std::max(sceneBounds(scene).radius(), 1e-6F));
}

std::string firstContractViolation(const Scene& scene) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (auto v = materialViolation(scene.materials[i], i); !v.empty()) {
      return v;
    }
  }
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    if (auto v = meshViolation(scene.meshes[i], i, scene.materials.size()); !v.empty()) {
      return v;
    }
  }
  return {};
}

}  // namespace vem::scene
