// Cube-map sampling on the CPU, as a GL samplerCube with linear filtering within a face reads
// level `level` of core/cube_map.h's faces (OpenGL face order and orientation). Used by the Embree
// renderer for the background and for mirror-like reflections, so that it shows what the GL
// renderer shows. Texels at a face's edge clamp to that face (GL without seamless filtering blends
// across edges; the difference is one texel at the edges).
#pragma once

#include <glm/vec3.hpp>

#include "core/cube_map.h"

namespace vem::render {

// dir non-zero (need not be unit); level clamped to the chain.
[[nodiscard]] glm::vec3 sampleCubeMap(const CubeMap& cube, glm::vec3 dir, int level = 0);

}  // namespace vem::render
