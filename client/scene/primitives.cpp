#include "client/scene/primitives.h"

#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

namespace vem::scene {

Mesh sphereMesh(glm::vec3 centre, float radius, int rings, int segments, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "sphere";
  mesh.material = material;
  for (int r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      const glm::vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                        float(std::sin(theta) * std::sin(phi)));
      mesh.positions.push_back(centre + radius * n);
      mesh.normals.push_back(n);
    }
  }
  const auto at = [&](int r, int s) { return std::uint32_t(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      // Counter-clockwise seen from outside: phi grows toward +Z, theta toward -Y.
      if (r > 0) {
        mesh.indices.insert(mesh.indices.end(), {at(r, s), at(r, s + 1), at(r + 1, s)});
      }
      if (r + 1 < rings) {
        mesh.indices.insert(mesh.indices.end(), {at(r, s + 1), at(r + 1, s + 1), at(r + 1, s)});
      }
    }
  }
  return mesh;
}

Mesh boxMesh(glm::vec3 min, glm::vec3 max, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "box";
  mesh.material = material;
  // Each face: its outward normal and two in-plane axes u, v with u x v = normal.
  const std::array<std::array<glm::vec3, 3>, 6> faces{{
      {glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)},
      {glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0)},
      {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1)},
      {glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)},
      {glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)},
      {glm::vec3(0, 0, -1), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0)},
  }};
  const glm::vec3 centre = 0.5F * (min + max);
  const glm::vec3 half = 0.5F * (max - min);
  for (const auto& [n, u, v] : faces) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (const glm::vec2 c :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      mesh.positions.push_back(centre + half * (n + c.x * u + c.y * v));
      mesh.normals.push_back(n);
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

Mesh groundPlane(float height, float size, float cx, float cz, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "ground";
  mesh.material = material;
  const float h = 0.5F * size;
  mesh.positions = {{cx - h, height, cz - h},
                    {cx - h, height, cz + h},
                    {cx + h, height, cz + h},
                    {cx + h, height, cz - h}};
  mesh.normals.assign(4, glm::vec3(0, 1, 0));
  mesh.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +Y
  return mesh;
}

}  // namespace vem::scene
