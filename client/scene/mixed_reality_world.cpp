#include "client/scene/mixed_reality_world.h"

#include <cstdint>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "client/scene/primitives.h"

namespace vem::scene {
namespace {

constexpr float kTileM = 0.5F;
constexpr int kTilesPerSide = 24;  // 12 m

// A square tile of the floor (y = 0), facing +Y.
Mesh tile(int i, int j, std::uint32_t material) {
  const float half = 0.5F * float(kTilesPerSide) * kTileM;
  Mesh mesh = groundPlane(0.0F, kTileM, -half + (float(i) + 0.5F) * kTileM,
                          -half + (float(j) + 0.5F) * kTileM, material);
  mesh.name = "tile " + std::to_string(i) + "," + std::to_string(j);
  return mesh;
}

// The wall: the plane z = zM from x = -3 to 3 m and y = 0 to heightM, facing +Z.
Mesh wall(float zM, float heightM, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "wall";
  mesh.positions = {{-3.0F, 0.0F, zM}, {3.0F, 0.0F, zM}, {3.0F, heightM, zM}, {-3.0F, heightM, zM}};
  mesh.normals.assign(4, glm::vec3(0.0F, 0.0F, 1.0F));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  return mesh;
}

Scene realSurfacesAndProxies(Scene* proxies) {
  Scene real;
  real.name = "the simulated real world";
  real.materials = {
      Material{.name = "tile light", .diffuseAlbedo = {0.62F, 0.58F, 0.52F}},
      Material{.name = "tile dark", .diffuseAlbedo = {0.28F, 0.30F, 0.34F}},
      Material{.name = "box", .diffuseAlbedo = {0.55F, 0.45F, 0.35F}},
      Material{.name = "wall", .diffuseAlbedo = {0.5F, 0.5F, 0.5F}},
  };
  for (int i = 0; i < kTilesPerSide; ++i) {
    for (int j = 0; j < kTilesPerSide; ++j) {
      real.meshes.push_back(tile(i, j, std::uint32_t((i + j) % 2)));
    }
  }
  Mesh box = boxMesh({-1.05F, 0.0F, -0.75F}, {-0.55F, 0.5F, -0.25F}, 2);
  box.name = "box";
  real.meshes.push_back(box);
  real.meshes.push_back(wall(-1.6F, 2.6F, 3));
  proxies->name = "proxies: box and wall";
  proxies->materials = {Material{.name = "proxy"}};
  box.material = 0;
  proxies->meshes = {box, wall(-1.6F, 2.6F, 0)};
  return real;
}

Scene syntheticObjects() {
  Scene objects;
  objects.name = "synthetic spheres";
  objects.materials = {
      Material{.name = "diffuse sphere", .diffuseAlbedo = glm::vec3(0.7F)},
      Material{.name = "gold sphere",
               .diffuseAlbedo = glm::vec3(0.0F),
               .lobe = Lobe::Ggx,
               .specularAlbedo = {0.9F, 0.7F, 0.35F},
               .roughness = 0.3F},
  };
  objects.meshes = {sphereMesh({-0.15F, 0.3F, 0.15F}, 0.3F, 32, 64, 0),
                    sphereMesh({0.55F, 0.2F, -0.1F}, 0.2F, 32, 64, 1)};
  objects.meshes[0].name = "diffuse sphere";
  objects.meshes[1].name = "gold sphere";
  return objects;
}

}  // namespace

MixedRealityWorld mixedRealityWorld() {
  MixedRealityWorld world;
  world.realSurfaces = realSurfacesAndProxies(&world.proxies);
  world.objects = syntheticObjects();
  world.realWithObjects = world.realSurfaces;
  world.realWithObjects.name = "the simulated real world with the objects";
  const auto offset = std::uint32_t(world.realWithObjects.materials.size());
  for (const Material& material : world.objects.materials) {
    world.realWithObjects.materials.push_back(material);
  }
  for (Mesh mesh : world.objects.meshes) {
    mesh.material += offset;
    world.realWithObjects.meshes.push_back(std::move(mesh));
  }
  world.plateViewFromWorld = glm::lookAt(
      glm::vec3(0.25F, 0.95F, 2.1F), glm::vec3(-0.05F, 0.28F, 0.0F), glm::vec3(0.0F, 1.0F, 0.0F));
  return world;
}

ViewCamera plateViewCamera(const MixedRealityWorld& world) {
  const PlateIntrinsicsPx& k = world.intrinsics;
  return pinholeViewCamera(world.plateViewFromWorld, k.fxPx, k.fyPx, k.cxPx, k.cyPx, k.widthPx,
                           k.heightPx, 0.05F, 60.0F);
}

}  // namespace vem::scene
