// render/soft_shadows.h: the solid angle each light casts its shadow from is its share of the
// sphere under a uniform sky, 0 for a sun, and 0 rather than infinite or NaN on a black or broken
// cube map.
#include "client/render/soft_shadows.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "core/default_pattern.h"
#include "core/env_map.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"

namespace vem::render {
namespace {

LightSet lightsFrom(const EnvMap& map, std::size_t n) {
  return generateLights(buildSamplingTables(map), defaultSamplingPattern(map.layout).first(n),
                        SamplerKind::Havran);
}

// Catches a cone taken from the light's power alone (without the radiance where it sits) or from
// the wrong side of the division: under a uniform sky of any radiance every one of N lights
// stands for 4 pi / N sr.
TEST(SoftShadows, UniformSkyGivesEachLightItsShareOfTheSphere) {
  for (const float radiance : {0.5F, 2.0F}) {
    const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(radiance));
    const CubeMap cube = cubeMapFromEnvMap(sky, 32, 1);
    const LightSet lights = lightsFrom(sky, 64);
    const std::vector<float> sr = shadowConeSolidAnglesSr(lights.lights, cube);
    ASSERT_EQ(sr.size(), 64U);
    for (const float s : sr) {
      EXPECT_NEAR(double(s), 4.0 * std::numbers::pi / 64.0, 0.01 * 4.0 * std::numbers::pi / 64.0);
    }
    // 8 lights stand for 1.57 sr each, over the cap.
    for (const float s : shadowConeSolidAnglesSr(lightsFrom(sky, 8).lights, cube)) {
      EXPECT_EQ(s, kSoftShadowMaxSr);
    }
  }
}

// A sun of one texel on a black sky: every light sits on it and keeps its hard shadow.
TEST(SoftShadows, SunKeepsAHardShadow) {
  EnvMap sun = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(0.0F));
  sun.set(40, 20, glm::vec3(1e5F));
  const CubeMap cube = cubeMapFromEnvMap(sun, 64, 1);
  const LightSet lights = lightsFrom(sun, 16);
  ASSERT_FALSE(lights.black);
  for (const float s : shadowConeSolidAnglesSr(lights.lights, cube)) {
    EXPECT_EQ(s, 0.0F);
  }
}

TEST(SoftShadows, BlackOrNanCubeGivesHardShadowsNotInfinities) {
  const EnvMap sky = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  const LightSet lights = lightsFrom(sky, 16);
  const EnvMap black = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(0.0F));
  for (const float s : shadowConeSolidAnglesSr(lights.lights, cubeMapFromEnvMap(black, 16, 1))) {
    EXPECT_EQ(s, 0.0F);
  }
  const EnvMap broken =
      EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(std::numeric_limits<float>::quiet_NaN()));
  for (const float s : shadowConeSolidAnglesSr(lights.lights, cubeMapFromEnvMap(broken, 16, 1))) {
    EXPECT_EQ(s, 0.0F);
  }
}

TEST(SoftShadows, ConeCosineOfAHemisphereIsZeroAndOfNothingOne) {
  EXPECT_FLOAT_EQ(coneCosineOf(0.0F), 1.0F);
  EXPECT_NEAR(double(coneCosineOf(2.0F * std::numbers::pi_v<float>)), 0.0, 1e-6);
}

}  // namespace
}  // namespace vem::render
