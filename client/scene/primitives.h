// Primitive meshes for the built-in scenes and tests, in the world frame of scene/scene.h
// (+Y up), counter-clockwise front faces outward (the plane's front face up, +Y), unit normals.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "client/scene/scene.h"

namespace vem::scene {

// A UV sphere: `rings` >= 2 latitude bands, `segments` >= 3 longitude bands, smooth normals.
[[nodiscard]] Mesh sphereMesh(glm::vec3 centre, float radius, int rings = 32, int segments = 64,
                              std::uint32_t material = 0);
// An axis-aligned box with flat faces (24 vertices).
[[nodiscard]] Mesh boxMesh(glm::vec3 min, glm::vec3 max, std::uint32_t material = 0);
// A square in the plane y = height, centred at (cx, cz), `size` on a side, facing +Y.
[[nodiscard]] Mesh groundPlane(float height, float size, float cx = 0.0F, float cz = 0.0F,
                               std::uint32_t material = 0);

}  // namespace vem::scene
