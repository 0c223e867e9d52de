// render/soft_shadows.h: the lights' strata tile the sphere and carry its power; a stratum is
// drawn from in proportion to its radiance and never outside itself; compact light (a sun) keeps a
// hard shadow; a black or broken cube gives hard shadows and finite numbers.
#include "client/render/soft_shadows.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/color.h"
#include "core/default_pattern.h"
#include "core/env_map.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"

namespace vem::render {
namespace {

constexpr double kPi = std::numbers::pi;

LightSet lightsFrom(const EnvMap& map, std::size_t n) {
  return generateLights(buildSamplingTables(map), defaultSamplingPattern(map.layout).first(n),
                        SamplerKind::Havran);
}

// A sphere map of radiance `west` where x < 0 and `east` where x >= 0 (pixel centres).
EnvMap halves(float west, float east) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 256, 128, glm::vec3(east));
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      if (pixelCentreDirection(map, x, y).x < 0.0) {
        map.set(x, y, glm::vec3(west));
      }
    }
  }
  return map;
}

// Catches texels left out of every stratum or counted twice, and a power taken from the light's
// rgb or its direction rather than from its stratum: under a uniform sky the strata hold every
// texel once and their powers sum to 4 pi L, each near the light's share.
TEST(SoftShadows, StrataTileTheSphereAndCarryItsPower) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(2.0F));
  const CubeMap cube = cubeMapFromEnvMap(sky, 64, 1);
  const LightSet lights = lightsFrom(sky, 64);
  const ShadowStrata strata = buildShadowStrata(lights.lights, cube);
  ASSERT_EQ(strata.facePx, 64);
  ASSERT_EQ(strata.offsets.size(), 65U);
  EXPECT_EQ(strata.offsets.back(), 6U * 64U * 64U);
  std::vector<int> seen(6 * 64 * 64, 0);
  for (const std::uint32_t t : strata.texel) ++seen[t];
  for (const int s : seen) ASSERT_EQ(s, 1);
  double total = 0.0;
  for (std::size_t i = 0; i < 64; ++i) {
    const double power = luminance(strata.powerRgb[i]);
    total += power;
    // Voronoi cells of an even pattern: within a factor of two of 4 pi L / 64.
    EXPECT_GT(power, 0.5 * 8.0 * kPi / 64.0) << "light " << i;
    EXPECT_LT(power, 2.0 * 8.0 * kPi / 64.0) << "light " << i;
    EXPECT_TRUE(strata.softAt(i)) << "light " << i;  // about 0.2 sr each
  }
  EXPECT_NEAR(total, 8.0 * kPi, 1e-3 * 8.0 * kPi);
}

// Catches draws uniform over solid angle (they would put half the draws west) and draws outside
// the stratum. Two lights, up and down, split the sphere into hemispheres; the upper one is three
// times brighter to the west, so three quarters of its draws lie west.
TEST(SoftShadows, DrawsFollowTheRadianceAndStayInTheStratum) {
  const CubeMap cube = cubeMapFromEnvMap(halves(3.0F, 1.0F), 64, 1);
  const std::vector<Light> lights = {Light{0, glm::vec3(0, 1, 0), glm::vec3(1.0F)},
                                     Light{1, glm::vec3(0, -1, 0), glm::vec3(1.0F)}};
  const ShadowStrata strata = buildShadowStrata(lights, cube);
  ASSERT_TRUE(strata.softAt(0));
  // Each hemisphere holds 2 pi (3 + 1) / 2 = 4 pi.
  EXPECT_NEAR(luminance(strata.powerRgb[0]), 4.0 * kPi, 0.02 * 4.0 * kPi);
  EXPECT_NEAR(luminance(strata.powerRgb[1]), 4.0 * kPi, 0.02 * 4.0 * kPi);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> u(0.0F, 1.0F);
  constexpr int kDraws = 20000;
  int west = 0;
  for (int k = 0; k < kDraws; ++k) {
    const glm::vec3 d = strata.sample(0, lights[0].dir, u(random), u(random), u(random));
    ASSERT_NEAR(double(glm::length(d)), 1.0, 1e-5);
    ASSERT_GE(d.y, 0.0F) << "a draw outside the upper stratum";
    if (d.x < 0.0F) ++west;
  }
  // 0.75 +- 5 sigma (sigma = 0.003), plus the bilinear seam's texels.
  EXPECT_NEAR(double(west) / kDraws, 0.75, 0.02);
}

// A sun of one texel on a black sky: every light sits on it and keeps its hard shadow, and its
// draws are its own direction.
TEST(SoftShadows, SunKeepsAHardShadow) {
  EnvMap sun = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(0.0F));
  sun.set(40, 20, glm::vec3(1e5F));
  const CubeMap cube = cubeMapFromEnvMap(sun, 64, 1);
  const LightSet lights = lightsFrom(sun, 16);
  ASSERT_FALSE(lights.black);
  const ShadowStrata strata = buildShadowStrata(lights.lights, cube);
  for (std::size_t i = 0; i < 16; ++i) {
    EXPECT_FALSE(strata.softAt(i)) << "light " << i << ": " << strata.spreadSr[i] << " sr";
    EXPECT_EQ(strata.sample(i, lights.lights[i].dir, 0.3F, 0.6F, 0.9F), lights.lights[i].dir);
  }
}

TEST(SoftShadows, BlackOrNanCubeGivesHardShadowsNotInfinities) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  const LightSet lights = lightsFrom(sky, 16);
  const EnvMap black = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(0.0F));
  const EnvMap broken =
      EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  for (const EnvMap* map : {&black, &broken}) {
    const ShadowStrata strata = buildShadowStrata(lights.lights, cubeMapFromEnvMap(*map, 16, 1));
    for (std::size_t i = 0; i < 16; ++i) {
      EXPECT_FALSE(strata.softAt(i));
      EXPECT_EQ(strata.powerRgb[i], glm::vec3(0.0F));
      EXPECT_TRUE(std::isfinite(strata.spreadSr[i]));
    }
  }
}

// A light with a broken direction takes no texels and stays hard; the others share the sphere.
TEST(SoftShadows, LightWithoutADirectionTakesNoStratum) {
  const CubeMap cube = cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F)), 16, 1);
  const std::vector<Light> lights = {
      Light{0, glm::vec3(0, 1, 0), glm::vec3(1.0F)},
      Light{1, glm::vec3(std::numeric_limits<float>::quiet_NaN()), glm::vec3(1.0F)},
      Light{2, glm::vec3(0, -1, 0), glm::vec3(1.0F)}};
  const ShadowStrata strata = buildShadowStrata(lights, cube);
  EXPECT_EQ(strata.offsets[2] - strata.offsets[1], 0U);
  EXPECT_FALSE(strata.softAt(1));
  EXPECT_EQ(strata.offsets.back(), 6U * 16U * 16U);
}

}  // namespace
}  // namespace vem::render
