// The local scene of a composite (issue 21, render/differential_composite.h): the real surfaces
// synthetic objects can shadow or be hidden by, put together with the objects for the two renders
// of differential rendering.
//
// - The floor is the plane y = 0 of the plate camera's world (its floor board, calib/core's
//   plate_camera.h): a square of kFloorSizeM on a side centred under the objects, facing +Y.
// - Proxy meshes (walls, tables; --local-scene FILE) join it as they are.
// - Every local mesh is drawn white (Lambertian, albedo 1): its render is its irradiance over pi,
//   and the real albedo comes from the plate (AlbedoEstimate), nobody types it in.
// World frame and units of scene/scene.h (metres, +Y up).
#pragma once

#include <vector>

#include "client/scene/scene.h"

namespace vem::scene {

inline constexpr float kFloorSizeM = 40.0F;

struct LocalComposition {
  Scene withObjects;               // the objects' meshes first, then the local ones (white)
  Scene localOnly;                 // the local meshes alone (white)
  std::vector<bool> objectMeshes;  // per mesh of withObjects: true for a synthetic object's
};

// The floor plane alone, centred under `centreWorld` (x, z).
[[nodiscard]] Scene floorOnly(glm::vec3 centreWorld = glm::vec3(0.0F));

// `objects` may be empty (then nothing is synthetic); `local` must hold at least one mesh.
[[nodiscard]] LocalComposition composeWithLocal(const Scene& objects, const Scene& local);

}  // namespace vem::scene
