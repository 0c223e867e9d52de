// Soft shadows for shading by ratio (issue 20, diffuse at few lights). A light of the core stands
// for a part of the sky, and at N = 16 that part is up to a twelfth of the sphere: its hard shadow
// is a sharp copy of the caster's outline where the sky casts a penumbra, and a ground point that
// sees the light's direction is lit by the whole part even where the caster hides most of it.
//
// With soft shadows each light has a stratum: the texels of the cube map (its level of at most
// kStrataFacePx a side) nearer to its direction than to any other light's, the sphere's Voronoi
// cells around the lights (the client has the lights, not the daemon's cells of light_cells.h).
// The strata tile the sphere. A shading point draws one direction per light from the light's
// stratum, with probability proportional to radiance x solid angle, and weighs it by the
// stratum's power times the cosine there; the visible fraction of the weights over the drawn
// directions is an unbiased estimate, per stratum, of the fraction of the stratum's irradiance
// that reaches the point (its visibility-weighted integral over the unshadowed one). Embree draws
// per pixel and averages over neighbouring pixels (embree/light_renderer.h); OpenGL draws k
// directions per light for the whole frame, one shadow map each (shadow_draws.h).
// Within a stratum the texels are ordered along a Z curve over the plane tangent at the light, so
// that a band of the table is a compact patch of sky: stratifying u1 (shadow_draws.h) then
// stratifies the draws in two dimensions (the face-row order left errors of 0.031 of the
// irradiance where the Z curve leaves 0.012, tests/gl/ratio_shading_test.cpp).
//
// A light whose stratum's light is compact keeps its hard shadow toward its own direction: a sun,
// a lamp, a softbox's share. Compact means an effective solid angle under kSoftShadowMinSr, taken
// from the spread of the stratum's radiance-weighted directions: for mean resultant length R of
// the unit directions weighted by luminance x sr, 4 pi (1 - R), which is exactly the solid angle
// of a uniformly bright cone (R = (1 + cos theta) / 2) and 0 for a single texel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/cube_map.h"
#include "core/light.h"

namespace vem::render {

inline constexpr float kSoftShadowMinSr = 0.01F;
// The strata's resolution: 64 px a side is 1.4 degrees a texel, 24576 texels.
inline constexpr int kStrataFacePx = 64;

struct ShadowStrata {
  int facePx = 0;  // of the texels below (texel_samples.h's indexing)
  // Per light: 1 when its shadow is soft (drawn from its stratum), 0 when hard.
  std::vector<std::uint8_t> soft;
  // Per light: the radiance x sr over its stratum (its power, in the map's units x sr).
  std::vector<glm::vec3> powerRgb;
  // Per light: its effective solid angle, sr (above).
  std::vector<float> spreadSr;
  // Light i's texels are texel[offsets[i] .. offsets[i + 1]), with cdf their cumulative share of
  // the stratum's luminance x sr (the last of each is 1). A stratum can hold no texel (a light
  // whose direction another light shares).
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> texel;
  std::vector<float> cdf;

  [[nodiscard]] bool softAt(std::size_t light) const { return soft[light] != 0; }
  // A direction in light `light`'s stratum drawn with probability proportional to luminance x
  // solid angle from (u1, u2, u3) in [0, 1)^3: u1 picks the texel, (u2, u3) the point in it. The
  // light's own direction when its shadow is hard.
  [[nodiscard]] glm::vec3 sample(std::size_t light, glm::vec3 lightDir, float u1, float u2,
                                 float u3) const;
};

// Three numbers in [0, 1) from a fixed hash of (a, b) (xorshift-multiply rounds): the draws'
// pattern, so a frame depends on neither the schedule nor a random state. Embree hashes (pixel,
// light), the shadow maps (light id, draw).
[[nodiscard]] glm::vec3 fixedUniforms(std::uint32_t a, std::uint32_t b);

// The strata of `lights` over `cube` (at least one level). Lights with a zero or non-finite
// direction, and a black or broken cube, get hard shadows and no texels.
[[nodiscard]] ShadowStrata buildShadowStrata(std::span<const Light> lights, const CubeMap& cube);

}  // namespace vem::render
