#include "client/scene/local_scene.h"

#include <cstdint>

#include "client/scene/primitives.h"
#include "util/contract.h"

namespace vem::scene {

Scene floorOnly(glm::vec3 centreWorld) {
  Scene floor;
  floor.name = "floor";
  floor.materials.push_back(Material{.name = "floor"});
  floor.meshes.push_back(groundPlane(0.0F, kFloorSizeM, centreWorld.x, centreWorld.z, 0));
  floor.meshes.back().name = "floor";
  return floor;
}

LocalComposition composeWithLocal(const Scene& objects, const Scene& local) {
  VEM_EXPECTS(!local.meshes.empty());
  const Material white{.name = "local (white)", .diffuseAlbedo = glm::vec3(1.0F)};
  LocalComposition out;
  out.withObjects.name = objects.name;
  out.withObjects.materials = objects.materials;
  out.withObjects.meshes = objects.meshes;
  out.objectMeshes.assign(objects.meshes.size(), true);
  const auto whiteInWith = std::uint32_t(out.withObjects.materials.size());
  out.withObjects.materials.push_back(white);
  out.localOnly.name = local.name;
  out.localOnly.materials = {white};
  for (Mesh mesh : local.meshes) {
    mesh.material = 0;
    out.localOnly.meshes.push_back(mesh);
    mesh.material = whiteInWith;
    out.withObjects.meshes.push_back(std::move(mesh));
    out.objectMeshes.push_back(false);
  }
  return out;
}

}  // namespace vem::scene
