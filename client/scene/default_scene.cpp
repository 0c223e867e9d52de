#include "client/scene/default_scene.h"

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "client/scene/obj_loader.h"
#include "client/scene/mixed_reality_world.h"
#include "client/scene/primitives.h"

namespace vem::scene {
namespace {

constexpr float kBunnyHeight = 1.0F;
constexpr float kGroundSize = 6.0F;
constexpr float kSphereRadius = 0.35F;
constexpr glm::vec3 kSphereCentre{1.1F, kSphereRadius, 0.3F};
constexpr glm::vec3 kBoxMin{-1.45F, 0.0F, -0.6F};
constexpr glm::vec3 kBoxMax{-0.85F, 0.6F, 0.0F};
constexpr float kStandInRadius = 0.5F;

enum MaterialSlot : std::uint32_t { kBunny = 0, kGround = 1, kSphere = 2, kBox = 3 };

Material lambertian(std::string name, glm::vec3 albedo) {
  Material m;
  m.name = std::move(name);
  m.diffuseAlbedo = albedo;
  return m;
}

std::vector<Material> defaultMaterials(bool glossy) {
  std::vector<Material> materials{
      lambertian("bunny", glm::vec3(0.75F)), lambertian("ground", glm::vec3(0.5F)),
      lambertian("sphere", {0.8F, 0.6F, 0.3F}), lambertian("box", {0.25F, 0.35F, 0.6F})};
  if (glossy) {
    Material& gold = materials[kSphere];
    gold.diffuseAlbedo = glm::vec3(0.0F);
    gold.lobe = Lobe::Ggx;
    gold.roughness = 0.3F;
    gold.specularAlbedo = {0.9F, 0.7F, 0.35F};
    Material& box = materials[kBox];
    box.lobe = Lobe::Blinn;
    box.exponent = 40.0F;
    box.specularAlbedo = glm::vec3(0.25F);
  }
  return materials;
}

// The bunny's meshes scaled to kBunnyHeight, standing on y = 0, centred in x and z.
std::vector<Mesh> standingBunny(Scene bunny) {
  const Bounds bounds = sceneBounds(bunny);
  const float scale = kBunnyHeight / (bounds.max.y - bounds.min.y);
  const glm::vec3 foot(bounds.centre().x, bounds.min.y, bounds.centre().z);
  for (Mesh& mesh : bunny.meshes) {
    for (glm::vec3& p : mesh.positions) {
      p = (p - foot) * scale;
    }
    mesh.material = kBunny;
    mesh.name = "bunny";
  }
  return std::move(bunny.meshes);
}

std::vector<Mesh> bunnyOrStandIn(const std::filesystem::path& path,
                                 std::vector<std::string>& notes) {
  auto loaded = loadObj(path);
  if (loaded && sceneBounds(loaded->scene).max.y > sceneBounds(loaded->scene).min.y) {
    return standingBunny(std::move(loaded->scene));
  }
  notes.push_back(fmt::format("the bunny could not be loaded ({}); a sphere stands in its place",
                              loaded ? std::string("it has no height") : loaded.error().message));
  Mesh standIn = sphereMesh(glm::vec3(0.0F, kStandInRadius, 0.0F), kStandInRadius, 32, 64, kBunny);
  standIn.name = "bunny stand-in";
  return {std::move(standIn)};
}

Scene spheresScene() {
  Scene scene;
  scene.name = "spheres";
  scene.materials = {lambertian("sphere", glm::vec3(0.8F)), lambertian("ground", glm::vec3(0.5F))};
  scene.meshes.push_back(sphereMesh(glm::vec3(0.0F, 0.5F, 0.0F), 0.5F, 32, 64, 0));
  scene.meshes.push_back(groundPlane(0.0F, 4.0F, 0.0F, 0.0F, 1));
  return scene;
}

Scene loneSphereScene() {
  Scene scene;
  scene.name = "sphere";
  scene.materials = {lambertian("sphere", glm::vec3(0.8F))};
  scene.meshes.push_back(sphereMesh(glm::vec3(0.0F), 1.0F, 32, 64, 0));
  return scene;
}

}  // namespace

std::filesystem::path defaultBunnyPath() {
  return std::filesystem::path(VEM_SHARED_DATA_DIR) / "models" / "bunny.obj";
}

DefaultScene defaultScene(const DefaultSceneOptions& options) {
  DefaultScene result;
  Scene& scene = result.scene;
  scene.name = options.glossy ? "default" : "diffuse";
  scene.materials = defaultMaterials(options.glossy);
  scene.meshes = bunnyOrStandIn(options.bunnyPath, result.notes);
  scene.meshes.push_back(groundPlane(0.0F, kGroundSize, 0.0F, 0.0F, kGround));
  scene.meshes.push_back(sphereMesh(kSphereCentre, kSphereRadius, 32, 64, kSphere));
  scene.meshes.push_back(boxMesh(kBoxMin, kBoxMax, kBox));
  return result;
}

std::optional<Scene> builtinScene(std::string_view name) {
  if (name == "default" || name == "diffuse") {
    return defaultScene({.glossy = name == "default"}).scene;
  }
  if (name == "spheres") {
    return spheresScene();
  }
  if (name == "sphere") {
    return loneSphereScene();
  }
  if (name == "mixed-reality") {
    return mixedRealityWorld().objects;
  }
  return std::nullopt;
}

}  // namespace vem::scene
