// The light's view for a shadow map (paper 004 section 5.2.1): an orthographic projection of the
// shadow casters' bounding sphere (scene::shadowCasterBounds: grounds left out) seen from a
// directional light, built from the light's direction alone so the lighting shader can rebuild it
// (shaders/light_view.glsl mirrors this file exactly).
//
// Conventions: dirToLight unit, world frame (core/light.h: from the scene toward the light). The
// eye sits at centre + dirToLight r and looks at the centre, up = +Y (or +X when |dir.y| > 0.99);
// x and y span [-r, r], depth [0, 2r] maps to clip z in [-1, 1] (OpenGL), nearest the light at -1.
// r = shadowFrameRadius(bounds): the bounds' half diagonal with a small margin.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "client/scene/scene.h"

namespace vem::gl {

[[nodiscard]] float shadowFrameRadius(const scene::Bounds& bounds);
[[nodiscard]] glm::vec3 lightUpHint(glm::vec3 dirToLight);
[[nodiscard]] glm::mat4 lightClipFromWorld(glm::vec3 dirToLight, const scene::Bounds& bounds);

}  // namespace vem::gl
