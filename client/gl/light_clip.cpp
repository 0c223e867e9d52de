#include "client/gl/light_clip.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace vem::gl {

float shadowFrameRadius(const scene::Bounds& bounds) {
  return std::max(bounds.radius() * 1.01F, 1e-3F);
}

glm::vec3 lightUpHint(glm::vec3 dirToLight) {
  return std::abs(dirToLight.y) > 0.99F ? glm::vec3(1.0F, 0.0F, 0.0F)
                                        : glm::vec3(0.0F, 1.0F, 0.0F);
}

glm::mat4 lightClipFromWorld(glm::vec3 dirToLight, const scene::Bounds& bounds) {
  const float r = shadowFrameRadius(bounds);
  const glm::vec3 centre = bounds.centre();
  const glm::mat4 lightFromWorld =
      glm::lookAt(centre + dirToLight * r, centre, lightUpHint(dirToLight));
  const glm::mat4 clipFromLight = glm::ortho(-r, r, -r, r, 0.0F, 2.0F * r);
  return clipFromLight * lightFromWorld;
}

}  // namespace vem::gl
