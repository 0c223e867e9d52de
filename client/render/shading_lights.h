// ShadingLights: the lights one frame is shaded with, in the form both renderers use, built from
// the frame's progressive light set (core/light.h) by the options the render plan chose (paper 004
// sections 4 and 5.2).
//
// - diffuse: the first lightCount lights of the set (a prefix is a good set: the progressive
//   property), rescaled so that they carry the whole set's power (by size / lightCount for the
//   generator's equal-power lights: the lightCount-light set; by the luminance ratio for unequal
//   ones such as clusters), or, with clustering,
//   their clusters (section 4.3, core/light_clustering.h). These light the diffuse term of every
//   surface (and the specular term when the scene has no glossy pass). diffuseLists: their
//   angular-region lists with reach pi/2 (section 4.1), empty when regions are off (every light is
//   then walked, and n . dir decides).
// - glossy (only when the plan has a glossy pass): L = the first lightCount lights unclustered,
//   H = its first highCount lights rescaled, and their region lists (section 4.2,
//   core/glossy_light_sets.h). The specular term of glossy surfaces walks these.
// - Shadows (section 5.2.1): the shadowedCount most important diffuse lights (largest luminance;
//   luminances within 1e-4 of each other, relative, are ties, kept in light order, so without
//   clustering the first ones whatever their colour) seed the shadow maps, one per slot. With
//   fewer maps than lights, the lights share them by shadow group (shadow_groups.h): by default
//   each map is rendered from the luminance-weighted mean direction of its group of lights
//   (ShadowGrouping::Cluster); NearestCaster keeps the paper's scheme, each map at its seed and
//   every other light reading the nearest seed's. shadowDirs gives each slot's direction;
//   shadowSlotOfDiffuse and shadowSlotOfLow give each light's slot (for an L light: the slot
//   whose direction is nearest), or -1 when there are no shadow maps (unshadowed).
// - lightsKey identifies the light directions that the shadow maps depend on: equal keys mean the
//   maps can be reused.
// Directions in the world frame of core/env_map.h; rgb in the irradiance units of core/light.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "client/render/shadow_groups.h"
#include "core/angular_regions.h"
#include "core/env_map.h"
#include "core/glossy_light_sets.h"
#include "core/light.h"

namespace vem::render {

inline constexpr std::size_t kMaxShadowMaps = 256;

struct LightingOptions {
  std::size_t lightCount = 256;     // N >= 1: the first N lights of the set
  std::size_t shadowedCount = 64;   // S in [0, kMaxShadowMaps]: shadow maps (0: no shadows)
  bool regions = true;              // angular-region culling
  bool glossyPass = false;          // L/H sets for glossy materials
  std::size_t highCount = 72;       // |H| (capped to N)
  std::size_t maxConeLights = 216;  // k: L lights per cone at most
  int clusterBudget = 0;            // Q > 0: cluster the diffuse lights (about Q), 0: no clustering
  MapLayout clusterLayout = MapLayout::Hemisphere;  // the map the lights came from (sets Q's area)
  ShadowGrouping shadowGrouping = ShadowGrouping::Cluster;  // how S < N maps are shared
};

// The fixed region geometry (built once per renderer; costs milliseconds).
struct LightingGeometry {
  AngularRegions diffuseRegions;
  GlossyRegions glossyRegions;
};
[[nodiscard]] LightingGeometry makeLightingGeometry();

struct ShadingLights {
  LightSet diffuse;
  RegionLightLists diffuseLists;
  std::optional<GlossyLightSets> glossy;
  std::vector<glm::vec3> shadowDirs;              // by slot: the direction of its map
  std::vector<std::int32_t> shadowSlotOfDiffuse;  // one per diffuse light
  std::vector<std::int32_t> shadowSlotOfLow;      // one per glossy->low light (empty without)
  // Soft shadows in the maps (shadow_draws.h): per diffuse light, how many consecutive slots from
  // its own hold directions drawn from its stratum of the sky (0: its map looks along its own
  // direction, a hard shadow), and by slot the draw's weight (the stratum's power over the draws;
  // 0 for a hard light's map). Both empty: every shadow is hard.
  std::vector<std::uint32_t> shadowDrawsOfDiffuse;
  std::vector<glm::vec3> shadowDrawWeights;
  std::size_t maxConeLights = 216;
  std::uint64_t lightsKey = 0;  // hash of shadowDirs
};

// The key of a list of shadow-map directions (FNV-1a over their bits): ShadingLights::lightsKey.
[[nodiscard]] std::uint64_t shadowDirsKey(std::span<const glm::vec3> dirs);

[[nodiscard]] ShadingLights buildShadingLights(const LightSet& lights,
                                               const LightingGeometry& geometry,
                                               const LightingOptions& options);

}  // namespace vem::render
