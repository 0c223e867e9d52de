// Glossy light sets: the two light sets L and H for glossy surfaces and their angular regions
// (paper 004 section 4.2), with a CPU reference of which lights shade a point.
//
// - L is the frame's full, progressive light set (low intensity each, |L| lights). H is its first
//   |H| lights (a prefix, so H's directions are those of L's progressive prefix) with rgb rescaled
//   by |L| / |H|: high.lights[k] is low.lights[k] with rgb x |L| / |H|. Both keep L's luminanceSr.
// - S_H: angular regions (angular_regions.h) over H with reach pi / 2 (section 4.1): the list of
//   regionOf(R) holds every light of H with R . dir > 0.
// - S_L: narrower regions over L. gamma is the smallest angle between two S_L centres (the paper's
//   "minimum angular distance between neighbouring centres"), the cone C(R, gamma / 2) is the
//   specular window. Region j of S_L lists the L lights within radiusRad[j] + gamma / 2 of its
//   centre (the paper says "within gamma"; this is the same when the region's lookup radius is
//   gamma / 2 and stays correct when the cube-map cell is wider), so the list of regionOf(R) holds
//   every L light inside C(R, gamma / 2) for any R.
// - Shading a reflected direction R: the L lights strictly inside C (R . dir > cos(gamma / 2)) with
//   weight 1, plus the H lights outside C and above R's horizon (0 < R . dir <= cos(gamma / 2))
//   with weight |L| / |H|: two strata, each light counted at most once. Lights with R . dir <= 0
//   are left out, so the reference assumes a lobe that vanishes on R's lower hemisphere.
// - Directions in the world frame of env_map.h (right-handed, +Y up); angles in radians; rgb in the
//   irradiance units of light.h.
// - The cone's cost can be capped (the paper's "we pick up only the first k light sources belonging
//   to C and scale up their power appropriately"): with maxConeLights = k and m > k lights inside
//   C, the first k (in light order, a progressive prefix) shade with weight m / k.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

#include "core/angular_regions.h"
#include "core/light.h"

namespace vem {

struct GlossyRegionsParams {
  int highRegionCount = kDefaultRegionCount;  // S_H
  int lowRegionCount = kDefaultRegionCount;   // S_L: more regions give a narrower cone
  int faceSize = kDefaultRegionFaceSize;
};

// Fixed before rendering, built once.
struct GlossyRegions {
  AngularRegions high;            // S_H
  AngularRegions low;             // S_L
  double coneHalfAngleRad = 0.0;  // gamma / 2
};

struct GlossyLightSets {
  LightSet low;                // L
  LightSet high;               // H
  RegionLightLists highLists;  // S_H lists, indices into high.lights
  RegionLightLists lowLists;   // S_L lists, indices into low.lights
};

// One light that shades a glossy point: low.lights[index] with its rgb times `weight`. Inside the
// cone the weight is 1 (the light comes from L); outside it is |L| / |H| (it comes from H, and
// high.lights[index] is that light already rescaled).
struct GlossyShadingLight {
  std::uint32_t index = 0;
  double weight = 1.0;
  bool inCone = false;
};

// lowRegionCount >= 2.
[[nodiscard]] GlossyRegions makeGlossyRegions(const GlossyRegionsParams& params = {});
// The first highCount lights of `low`, rgb x |L| / highCount; 1 <= highCount <= |L| (or 0 when L
// is empty).
[[nodiscard]] LightSet highLightSet(const LightSet& low, std::size_t highCount);
[[nodiscard]] GlossyLightSets makeGlossyLightSets(const LightSet& low, std::size_t highCount,
                                                  const GlossyRegions& regions);
// The lights that shade a point whose ideal reflected direction is reflectedDir (non-zero): the L
// lights inside the cone in light order (at most maxConeLights of them, rescaled), then the H
// lights outside it in light order. maxConeLights >= 1.
[[nodiscard]] std::vector<GlossyShadingLight> glossyLightsFor(
    glm::dvec3 reflectedDir, const GlossyLightSets& sets, const GlossyRegions& regions,
    std::size_t maxConeLights = std::numeric_limits<std::size_t>::max());

}  // namespace vem
