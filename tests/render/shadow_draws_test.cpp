// render/shadow_draws.h: the maps beyond N go to the soft lights' strata within the budget; each
// soft light's draws lie in its own stratum and their weights carry its stratum's power; hard
// lights keep one map along their own direction; no spare maps, no change; the same lights and
// cube give the same maps (so a frame with unchanged lights reuses them).
#include "client/render/shadow_draws.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/color.h"
#include "core/default_pattern.h"
#include "core/env_map.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"

namespace vem::render {
namespace {

ShadingLights lightsOf(const EnvMap& map, std::size_t n) {
  LightingOptions options;
  options.lightCount = n;
  options.shadowedCount = n;
  options.regions = false;
  const LightSet set = generateLights(buildSamplingTables(map),
                                      defaultSamplingPattern(map.layout).first(n),
                                      SamplerKind::Havran);
  return buildShadingLights(set, makeLightingGeometry(), options);
}

std::size_t nearestLight(const std::vector<Light>& lights, glm::vec3 dir) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < lights.size(); ++i) {
    if (glm::dot(lights[i].dir, dir) > glm::dot(lights[best].dir, dir)) best = i;
  }
  return best;
}

// Catches draws outside their light's stratum, weights that do not add up to the stratum's power
// (a light's shadow would then count more or less than its light), slots that overlap or pass the
// budget, and a key left as it was (the old maps would be reused).
TEST(ShadowDraws, SpareMapsGoToTheSoftLightsWithinTheBudget) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(1.0F));
  const CubeMap cube = cubeMapFromEnvMap(sky, 64, 1);
  ShadingLights lights = lightsOf(sky, 16);
  const std::uint64_t hardKey = lights.lightsKey;
  const ShadowStrata strata = buildShadowStrata(lights.diffuse.lights, cube);
  ASSERT_TRUE(spendShadowMapsOnStrata(lights, strata, 256));
  ASSERT_EQ(lights.shadowDirs.size(), 256U);  // 16 lights, 1 + 240 / 16 = 16 draws each
  ASSERT_EQ(lights.shadowDrawWeights.size(), 256U);
  EXPECT_NE(lights.lightsKey, hardKey);
  EXPECT_EQ(lights.lightsKey, shadowDirsKey(lights.shadowDirs));
  for (std::size_t i = 0; i < 16; ++i) {
    ASSERT_EQ(lights.shadowDrawsOfDiffuse[i], 16U);
    ASSERT_EQ(lights.shadowSlotOfDiffuse[i], std::int32_t(16 * i));
    glm::vec3 weight(0.0F);
    for (std::size_t j = 0; j < 16; ++j) {
      const std::size_t slot = 16 * i + j;
      weight += lights.shadowDrawWeights[slot];
      // In the stratum, up to the texel a draw lies in (1.4 degrees, whose centre decides).
      const glm::vec3 d = lights.shadowDirs[slot];
      const std::size_t nearest = nearestLight(lights.diffuse.lights, d);
      EXPECT_LT(glm::dot(lights.diffuse.lights[nearest].dir, d) -
                    glm::dot(lights.diffuse.lights[i].dir, d),
                0.03F)
          << "light " << i << ", draw " << j;
    }
    EXPECT_NEAR(luminance(weight), luminance(strata.powerRgb[i]),
                1e-5 * luminance(strata.powerRgb[i]));
  }
}

// A sun keeps its hard shadow: its light's one map looks along its own direction and weighs 0
// (the shader then uses the light's own rgb), and the soft lights share what is left.
TEST(ShadowDraws, HardLightsKeepOneMapAlongTheirOwnDirection) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(0.5F));
  map.set(40, 20, glm::vec3(5e4F));  // a sun that takes most of the lights
  const CubeMap cube = cubeMapFromEnvMap(map, 64, 1);
  ShadingLights lights = lightsOf(map, 16);
  const ShadowStrata strata = buildShadowStrata(lights.diffuse.lights, cube);
  std::size_t hard = 0;
  for (std::size_t i = 0; i < 16; ++i) hard += strata.softAt(i) ? 0 : 1;
  ASSERT_GT(hard, 0U);
  ASSERT_LT(hard, 16U);
  ASSERT_TRUE(spendShadowMapsOnStrata(lights, strata, 64));
  EXPECT_LE(lights.shadowDirs.size(), 64U);
  for (std::size_t i = 0; i < 16; ++i) {
    const auto slot = std::size_t(lights.shadowSlotOfDiffuse[i]);
    if (strata.softAt(i)) {
      EXPECT_EQ(lights.shadowDrawsOfDiffuse[i], 1 + (64 - 16) / (16 - hard));
    } else {
      EXPECT_EQ(lights.shadowDrawsOfDiffuse[i], 0U);
      EXPECT_EQ(lights.shadowDirs[slot], lights.diffuse.lights[i].dir);
      EXPECT_EQ(lights.shadowDrawWeights[slot], glm::vec3(0.0F));
    }
  }
}

TEST(ShadowDraws, NoSpareMapsLeavesTheLightsAsTheyWere) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(1.0F));
  const CubeMap cube = cubeMapFromEnvMap(sky, 64, 1);
  ShadingLights lights = lightsOf(sky, 16);
  const ShadingLights before = lights;
  const ShadowStrata strata = buildShadowStrata(lights.diffuse.lights, cube);
  // 16 maps for 16 lights, and 31 (one draw short of two per soft light).
  for (const std::size_t budget : {std::size_t(16), std::size_t(31)}) {
    EXPECT_FALSE(spendShadowMapsOnStrata(lights, strata, budget));
    EXPECT_EQ(lights.shadowDirs, before.shadowDirs);
    EXPECT_EQ(lights.shadowSlotOfDiffuse, before.shadowSlotOfDiffuse);
    EXPECT_TRUE(lights.shadowDrawsOfDiffuse.empty());
    EXPECT_EQ(lights.lightsKey, before.lightsKey);
  }
}

TEST(ShadowDraws, SameLightsAndCubeGiveTheSameMaps) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(1.0F));
  const CubeMap cube = cubeMapFromEnvMap(sky, 64, 1);
  ShadingLights a = lightsOf(sky, 16);
  ShadingLights b = a;
  ASSERT_TRUE(spendShadowMapsOnStrata(a, buildShadowStrata(a.diffuse.lights, cube), 128));
  ASSERT_TRUE(spendShadowMapsOnStrata(b, buildShadowStrata(b.diffuse.lights, cube), 128));
  EXPECT_EQ(a.shadowDirs, b.shadowDirs);
  EXPECT_EQ(a.lightsKey, b.lightsKey);
}

}  // namespace
}  // namespace vem::render
