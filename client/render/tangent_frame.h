// An orthonormal frame around a unit direction: t, b with t x b = z, built from the world axis
// least aligned with z (+Y unless |z.y| >= 0.9, then +X). The one convention for the lobe samples
// of environment_lighting.cpp and the strata's Z-curve order of soft_shadows.cpp (the GLSL's
// frameAround in shaders/lighting.frag.glsl follows it).
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace vem::render {

struct TangentFrame {
  glm::vec3 t;
  glm::vec3 b;
};

[[nodiscard]] inline TangentFrame tangentFrameAround(glm::vec3 z) {
  const glm::vec3 helper = std::abs(z.y) < 0.9F ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, z));
  return {t, glm::cross(z, t)};
}

}  // namespace vem::render
