#include "core/glossy_light_sets.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "util/contract.h"

namespace vem {
namespace {

double highWeight(const GlossyLightSets& sets) {
  const std::size_t highCount = sets.high.lights.size();
  return highCount == 0 ? 1.0 : double(sets.low.lights.size()) / double(highCount);
}

double cosineTo(glm::dvec3 unitDir, const Light& light) {
  return glm::dot(unitDir, glm::normalize(glm::dvec3(light.dir)));
}

}  // namespace

GlossyRegions makeGlossyRegions(const GlossyRegionsParams& params) {
  VEM_EXPECTS(params.lowRegionCount >= 2);
  GlossyRegions regions;
  regions.high = makeAngularRegions(params.highRegionCount, params.faceSize);
  regions.low = makeAngularRegions(params.lowRegionCount, params.faceSize);
  regions.coneHalfAngleRad = 0.5 * minCentreSeparationRad(regions.low);
  return regions;
}

LightSet highLightSet(const LightSet& low, std::size_t highCount) {
  const std::size_t lowCount = low.lights.size();
  VEM_EXPECTS(highCount <= lowCount && (highCount > 0 || lowCount == 0));
  LightSet high{{}, low.luminanceSr, low.black};
  if (highCount == 0) return high;
  const float scale = float(double(lowCount) / double(highCount));
  high.lights.assign(low.lights.begin(), low.lights.begin() + std::ptrdiff_t(highCount));
  for (Light& light : high.lights) light.rgb *= scale;
  return high;
}

GlossyLightSets makeGlossyLightSets(const LightSet& low, std::size_t highCount,
                                    const GlossyRegions& regions) {
  GlossyLightSets sets;
  sets.low = low;
  sets.high = highLightSet(low, highCount);
  sets.highLists = visibleLightLists(regions.high, sets.high);
  sets.lowLists = regionLightLists(regions.low, sets.low.lights, regions.coneHalfAngleRad);
  return sets;
}

std::vector<GlossyShadingLight> glossyLightsFor(glm::dvec3 reflectedDir,
                                                const GlossyLightSets& sets,
                                                const GlossyRegions& regions,
                                                std::size_t maxConeLights) {
  VEM_EXPECTS(maxConeLights >= 1);
  const glm::dvec3 r = glm::normalize(reflectedDir);
  const double cosHalfAngle = std::cos(regions.coneHalfAngleRad);
  std::vector<GlossyShadingLight> out;
  for (const std::uint32_t index : sets.lowLists.lightsOf(regions.low.regionOf(r))) {
    if (cosineTo(r, sets.low.lights[index]) > cosHalfAngle) out.push_back({index, 1.0, true});
  }
  if (out.size() > maxConeLights) {  // keep the progressive prefix, scaled up to the whole cone
    const double scale = double(out.size()) / double(maxConeLights);
    out.resize(maxConeLights);
    for (GlossyShadingLight& light : out) light.weight = scale;
  }
  const double weight = highWeight(sets);
  for (const std::uint32_t index : sets.highLists.lightsOf(regions.high.regionOf(r))) {
    const double cosine = cosineTo(r, sets.high.lights[index]);
    if (cosine > 0.0 && cosine <= cosHalfAngle) out.push_back({index, weight, false});
  }
  return out;
}

}  // namespace vem
