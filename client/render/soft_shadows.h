// Soft shadows for shading by ratio (issue 20, diffuse at few lights). A light of the core stands
// for a part of the sky: the Havran sampler gives every light the same power, so its share of the
// sphere is about its irradiance over the radiance where it sits,
//   Omega_i = Y(rgb_i) / Y(L(dir_i))   (sr; L from the cube map's level 0).
// At N = 16 a light stands for up to a twelfth of the sphere, and its hard shadow is a sharp copy
// of the caster's outline where the sky casts a penumbra. With soft shadows a light casts the
// shadow of the cone of solid angle Omega_i around its direction instead: its visibility is the
// unblocked fraction of the cone. A light under kSoftShadowMinSr (a sun, a lamp, a softbox's
// share) keeps its hard shadow, and a cone is at most kSoftShadowMaxSr (the wider ones come from
// dim parts of the sky, whose lights lie far apart).
// Both renderers estimate the same fraction: Embree with one jittered ray per light and pixel
// and a filter over neighbouring pixels (embree/light_renderer.h), OpenGL by percentage-closer
// soft shadows in the light's shadow map (gl/shaders/shadow_lookup.glsl).
#pragma once

#include <span>
#include <vector>

#include "core/cube_map.h"
#include "core/light.h"

namespace vem::render {

inline constexpr float kSoftShadowMinSr = 0.01F;
inline constexpr float kSoftShadowMaxSr = 1.0F;

// Per light, Omega_i above clamped to kSoftShadowMaxSr, or 0 (a hard shadow) under
// kSoftShadowMinSr, where the cube map is black in the light's direction, or where either
// luminance is not finite.
[[nodiscard]] std::vector<float> shadowConeSolidAnglesSr(std::span<const Light> lights,
                                                         const CubeMap& cube);

// The cosine of the half-angle of a cone of solid angle `solidAngleSr` (0 .. 2 pi): 1 - Omega / 2 pi.
[[nodiscard]] float coneCosineOf(float solidAngleSr);

}  // namespace vem::render
