// Cube-map sampling on the CPU, as a GL samplerCube with linear filtering within a face reads
// level `level` of core/cube_map.h's faces (OpenGL face order and orientation). Used by the Embree
// renderer for the background and for mirror-like reflections, so that it shows what the GL
// renderer shows. Texels at a face's edge clamp to that face (GL without seamless filtering blends
// across edges; the difference is one texel at the edges).
#pragma once

#include <glm/vec3.hpp>

#include "core/cube_map.h"
#include "core/env_map.h"

namespace vem::render {

// dir non-zero (need not be unit); level clamped to the chain.
[[nodiscard]] glm::vec3 sampleCubeMap(const CubeMap& cube, glm::vec3 dir, int level = 0);

// The same read without seams: a texel beyond the face's edge is read from the neighbouring face
// (the texel under the direction through its centre), as GL samples with
// GL_TEXTURE_CUBE_MAP_SEAMLESS. For the small derived cubes of environment_lighting.h, whose texels
// span several degrees: clamping there would leave a step of half a texel's variation at every
// edge.
[[nodiscard]] glm::vec3 sampleCubeMapSeamless(const CubeMap& cube, glm::vec3 dir, int level = 0);

// The background along a primary ray: level 0 along dir, except below the horizon (dir.y < 0) of a
// cube made from a Hemisphere map (vemd's stream), which holds nothing there: black. Without that
// cut, linear filtering blends the sky texels just above the horizon half a texel below it (0.45
// degrees at 128 px), a grey band at the top of vemview's default view, whose upper edge is the
// horizon. The GL background shader (client/gl/shaders/background.frag.glsl) does the same.
[[nodiscard]] glm::vec3 sampleBackground(const CubeMap& cube, MapLayout coverage, glm::vec3 dir);

}  // namespace vem::render
