#include "calib/core/frame_around.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace vem::calib {

glm::dmat3 frameAround(const glm::dvec3& axis) {
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 x = glm::normalize(glm::cross(helper, axis));
  return glm::dmat3(x, glm::cross(axis, x), axis);
}

}  // namespace vem::calib
