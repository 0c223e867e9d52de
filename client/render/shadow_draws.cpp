#include "client/render/shadow_draws.h"

#include <cstdint>
#include <vector>

namespace vem::render {

bool spendShadowMapsOnStrata(ShadingLights& lights, const ShadowStrata& strata,
                             std::size_t maxShadowMaps) {
  const std::vector<Light>& diffuse = lights.diffuse.lights;
  const std::size_t n = diffuse.size();
  if (n == 0 || strata.soft.size() != n || maxShadowMaps <= n) return false;
  std::size_t softCount = 0;
  for (std::size_t i = 0; i < n; ++i) softCount += strata.softAt(i) ? 1 : 0;
  if (softCount == 0) return false;
  const std::size_t k = 1 + (maxShadowMaps - n) / softCount;
  if (k < 2) return false;
  std::vector<glm::vec3> dirs;
  std::vector<std::int32_t> slots(n, -1);
  std::vector<std::uint32_t> draws(n, 0);
  std::vector<glm::vec3> weights;
  for (std::size_t i = 0; i < n; ++i) {
    slots[i] = std::int32_t(dirs.size());
    if (!strata.softAt(i)) {
      dirs.push_back(diffuse[i].dir);
      weights.push_back(glm::vec3(0.0F));
      continue;
    }
    draws[i] = std::uint32_t(k);
    const glm::vec3 weight = strata.powerRgb[i] / float(k);
    for (std::size_t j = 0; j < k; ++j) {
      const glm::vec3 u = fixedUniforms(diffuse[i].id, std::uint32_t(j));
      const float u1 = (float(j) + u.x) / float(k);
      dirs.push_back(strata.sample(i, diffuse[i].dir, u1, u.y, u.z));
      weights.push_back(weight);
    }
  }
  lights.shadowDirs = std::move(dirs);
  lights.shadowSlotOfDiffuse = std::move(slots);
  lights.shadowDrawsOfDiffuse = std::move(draws);
  lights.shadowDrawWeights = std::move(weights);
  lights.lightsKey = shadowDirsKey(lights.shadowDirs);
  return true;
}

}  // namespace vem::render
