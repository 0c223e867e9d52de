#include "client/render/shading_lights.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <span>

#include <glm/glm.hpp>

#include "core/color.h"
#include "core/light_clustering.h"

namespace vem::render {
namespace {

LightSet prefixOf(const LightSet& lights, std::size_t count) {
  LightSet prefix;
  prefix.luminanceSr = lights.luminanceSr;
  prefix.black = lights.black;
  const std::size_t n = std::min(count, lights.lights.size());
  prefix.lights.assign(lights.lights.begin(), lights.lights.begin() + std::ptrdiff_t(n));
  // The prefix carries the whole set's power: for the sampler's equal-power lights that is
  // size / n (the n-light set has the same directions with shares size / n times larger,
  // core/light_generator.h); for unequal lights (clusters) the ratio of the luminances.
  double all = 0.0;
  double kept = 0.0;
  for (std::size_t i = 0; i < lights.lights.size(); ++i) {
    const double y = luminance(lights.lights[i].rgb);
    all += y;
    kept += i < n ? y : 0.0;
  }
  const float scale = kept > 0.0 ? float(all / kept)
                      : n == 0   ? 1.0F
                                 : float(double(lights.lights.size()) / double(n));
  for (Light& light : prefix.lights) {
    light.rgb *= scale;
  }
  return prefix;
}

// Luminances this close (relative) are ties. The generator's lights carry equal shares, but their
// float rgb (the map's colour at the sample times the share) give luminances that differ in the
// last bits, by colour: without a tolerance those bits chose the casters (issue 17: on park.exr,
// whose sun is pure blue, every one of the 64 casters of 1024 lights sat in the sun and the other
// lights borrowed maps up to 180 degrees away).
constexpr double kLuminanceTieRelative = 1e-4;

// The S lights of largest luminance (ties in light order), by slot: the shadow maps' seeds.
// Luminances are compared by their distance to the largest in steps of kLuminanceTieRelative
// (integer keys: a strict weak order), so lights within a step of each other keep their order.
std::vector<std::uint32_t> shadowCastersOf(const LightSet& diffuse, std::size_t shadowedCount) {
  std::vector<std::uint32_t> order(diffuse.lights.size());
  std::iota(order.begin(), order.end(), 0U);
  double largest = 0.0;
  for (const Light& light : diffuse.lights) largest = std::max(largest, luminance(light.rgb));
  std::vector<std::int64_t> rank(diffuse.lights.size(), 0);
  if (largest > 0.0) {
    for (std::size_t i = 0; i < rank.size(); ++i) {
      const double y = std::max(luminance(diffuse.lights[i].rgb), largest * 1e-30);
      rank[i] = std::llround(std::log(largest / y) / std::log1p(kLuminanceTieRelative));
    }
  }
  std::ranges::stable_sort(order, {}, [&](std::uint32_t i) { return rank[i]; });
  order.resize(std::min({shadowedCount, kMaxShadowMaps, order.size()}));
  return order;
}

}  // namespace

std::uint64_t shadowDirsKey(std::span<const glm::vec3> dirs) {
  std::uint64_t key = 1469598103934665603ULL ^ dirs.size();  // FNV-1a over the directions
  for (const glm::vec3& d : dirs) {
    for (float c : {d.x, d.y, d.z}) {
      key = (key ^ std::bit_cast<std::uint32_t>(c)) * 1099511628211ULL;
    }
  }
  return key;
}


LightingGeometry makeLightingGeometry() {
  return LightingGeometry{makeAngularRegions(), makeGlossyRegions()};
}

ShadingLights buildShadingLights(const LightSet& lights, const LightingGeometry& geometry,
                                 const LightingOptions& options) {
  ShadingLights out;
  const LightSet prefix = prefixOf(lights, std::max<std::size_t>(options.lightCount, 1));
  if (options.clusterBudget > 0 && !prefix.lights.empty()) {
    ClusteringParams params;
    params.clusterBudget = options.clusterBudget;
    params.layout = options.clusterLayout;
    out.diffuse = clusterLights(prefix, params).clusters;
  } else {
    out.diffuse = prefix;
  }
  if (options.regions) {
    out.diffuseLists = visibleLightLists(geometry.diffuseRegions, out.diffuse);
  }
  if (options.glossyPass && !prefix.lights.empty()) {
    const std::size_t high = std::clamp<std::size_t>(options.highCount, 1, prefix.lights.size());
    out.glossy = makeGlossyLightSets(prefix, high, geometry.glossyRegions);
  }
  ShadowGroups groups =
      groupShadows(out.diffuse.lights, shadowCastersOf(out.diffuse, options.shadowedCount),
                   options.shadowGrouping);
  out.shadowDirs = std::move(groups.dirs);
  out.shadowSlotOfDiffuse = std::move(groups.slots);
  if (out.glossy) {
    out.shadowSlotOfLow = nearestShadowSlots(out.glossy->low.lights, out.shadowDirs);
  }
  out.maxConeLights = std::max<std::size_t>(options.maxConeLights, 1);
  out.lightsKey = shadowDirsKey(out.shadowDirs);
  return out;
}

}  // namespace vem::render
