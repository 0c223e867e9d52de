// frameAround: a right-handed orthonormal frame whose third column (z) is a given unit direction,
// the other two chosen from whichever world axis is far from it (x, or y when the direction lies
// near x). Used to turn a view's mean ray into a camera-from-local rotation and to face a
// simulated board toward a direction. Columns: x, y = z cross x, z = axis.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace vem::calib {

// `axis` must be a unit vector.
[[nodiscard]] glm::dmat3 frameAround(const glm::dvec3& axis);

}  // namespace vem::calib
