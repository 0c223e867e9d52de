// Soft shadows in shadow maps (OpenGL's, issue 20; the strata are soft_shadows.h's). A shadow map
// looks along one direction, so it cannot draw a direction per pixel as Embree does. When a frame
// has more maps to spend (S) than diffuse lights (N), the spare maps go to the soft lights instead:
// each soft light gets k >= 2 consecutive slots, k = 1 + (S - N) / (soft lights), whose maps look
// along k directions drawn from its stratum, stratified over its table (draw j takes u1 in
// [j / k, (j + 1) / k)) and the same for every pixel. Each draw weighs the stratum's power / k
// times the cosine at its direction, and a pixel's visible share of the weights estimates the
// share of the stratum's irradiance that reaches it, as Embree's per-pixel draws do. Hard lights
// keep one map along their own direction. Fewer than two draws per soft light fit: nothing
// changes (every shadow stays hard).
// The draws follow a fixed hash of (light id, draw): the same lights and cube give the same maps.
#pragma once

#include <cstddef>

#include "client/render/shading_lights.h"
#include "client/render/soft_shadows.h"

namespace vem::render {

// Rewrites `lights`' shadow slots (shadowDirs, shadowSlotOfDiffuse, shadowDrawsOfDiffuse,
// shadowDrawWeights, lightsKey) to spend up to maxShadowMaps maps on the strata of its diffuse
// lights (`strata` built on lights.diffuse). Returns whether any light got draws. The glossy L/H
// sets' slots are left alone: shading by ratio does not read them.
bool spendShadowMapsOnStrata(ShadingLights& lights, const ShadowStrata& strata,
                             std::size_t maxShadowMaps);

}  // namespace vem::render
