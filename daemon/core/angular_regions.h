// Angular regions: overlapping cones of directions that cover the sphere, found in O(1) through a
// cube-map table, and per frame the lights relevant to each region (paper 004 sections 4.1, 4.2 and
// 5.2). A renderer looks up the region of a normal (or of a reflected direction) and walks only
// that region's light list.
//
// - Geometry (fixed before rendering, built once): centres = fibonacciSphere(count)
// (sphere_points.h),
//   and a cube-map table (cube_map_lookup.h, 6 F^2 texels) whose texels hold the index of the
//   centre nearest to the texel's centre direction. regionOf(dir) is one table read.
// - radiusRad[i] is conservative: every direction whose texel maps to region i lies within
//   radiusRad[i] of centres[i]. It is the largest, over those texels, of angle(centre, texel
//   centre)
//   + cubeTexelRadiusRad(texel), plus kRegionRadiusMarginRad for rounding (triangle inequality).
// - Light lists (per frame): region i lists the lights whose direction d has
//   angle(centres[i], d) < radiusRad[i] + reachRad. With reachRad = pi/2 (section 4.1) the list of
//   regionOf(n) holds every light with n . d > 0, i.e. every light that can reach a surface with
//   normal n. A narrow reachRad gives the regions S_L of section 4.2 (glossy_light_sets.h).
//   Lists hold indices into LightSet::lights in ascending order, so a prefix of a list is itself
//   progressive (Observation 1 of the paper).
// - Directions in the world frame of env_map.h (right-handed, +Y up); angles in radians.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <numbers>
#include <span>
#include <vector>

#include "core/light.h"

namespace vem {

inline constexpr int kDefaultRegionCount = 200;    // paper 004 section 6: 200 angular regions
inline constexpr int kDefaultRegionFaceSize = 32;  // cube-map texels per face edge
inline constexpr double kRegionRadiusMarginRad = 1e-9;
inline constexpr double kHemisphereReachRad = std::numbers::pi / 2;

struct AngularRegions {
  std::vector<glm::dvec3> centres;           // unit
  std::vector<double> radiusRad;             // conservative radius of each region
  int faceSize = 0;                          // F
  std::vector<std::uint32_t> regionOfTexel;  // 6 F^2 entries, by cubeTexelIndex

  [[nodiscard]] std::size_t count() const { return centres.size(); }
  // The region whose table texel holds `dir` (non-zero, need not be unit). O(1).
  [[nodiscard]] std::uint32_t regionOf(glm::dvec3 dir) const;
};

// regionCount >= 1 centres, faceSize >= 1. Cost O(6 F^2 regionCount), paid once.
[[nodiscard]] AngularRegions makeAngularRegions(int regionCount = kDefaultRegionCount,
                                                int faceSize = kDefaultRegionFaceSize);

// Smallest angle between two distinct centres (the paper's gamma for the regions S_L).
// O(count^2): centres are few (hundreds) and fixed. Needs count >= 2.
[[nodiscard]] double minCentreSeparationRad(const AngularRegions& regions);

struct RegionLightLists {
  // count + 1 entries: region i's lights are lightIndices[offsets[i], offsets[i + 1]).
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> lightIndices;  // indices into LightSet::lights, ascending per region

  [[nodiscard]] std::span<const std::uint32_t> lightsOf(std::uint32_t region) const;
  // Mean list length over the regions divided by lightCount (0 when lightCount is 0).
  [[nodiscard]] double meanFraction(std::size_t lightCount) const;
};

// Lights with angle(centres[i], dir) < radiusRad[i] + reachRad, for every region i.
// Cost O(count x lights), the size of the wide lists themselves.
[[nodiscard]] RegionLightLists regionLightLists(const AngularRegions& regions,
                                                std::span<const Light> lights, double reachRad);
// Section 4.1: the lights that can reach some normal of each region (reachRad = pi / 2).
[[nodiscard]] RegionLightLists visibleLightLists(const AngularRegions& regions,
                                                 const LightSet& lights);

}  // namespace vem
