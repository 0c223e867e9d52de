// Lights from maps: white furnace, energy sums, the progressive prefix, and the hard cases that
// must stay numerically stable (black map, a sun-like hot pixel of 1e8 over 1e-3 at the zenith, the
// horizon and the seam, NaN/Inf/negative pixels, a 4096 x 2048 map, N = 1 and N = 65536).
#include "core/light_generator.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/default_pattern.h"
#include "core/irradiance.h"
#include "core/sphere_points.h"
#include "support/test_maps.h"

namespace vem {
namespace {

constexpr SamplerKind kBoth[] = {SamplerKind::Havran, SamplerKind::Standard};

LightSet lightsFor(const EnvMap& map, std::size_t count, SamplerKind kind) {
  return generateLights(buildSamplingTables(map),
                        defaultSamplingPattern(map.layout).first(count), kind);
}

glm::dvec3 rgbSum(const LightSet& set) {
  glm::dvec3 sum(0);
  for (const Light& l : set.lights) sum += glm::dvec3(l.rgb);
  return sum;
}

// No NaN or Inf, unit directions, strictly positive power (unless the map is black).
void expectWellFormed(const LightSet& set, const std::string& what) {
  for (const Light& l : set.lights) {
    ASSERT_TRUE(std::isfinite(l.dir.x) && std::isfinite(l.dir.y) && std::isfinite(l.dir.z)) << what;
    ASSERT_TRUE(std::isfinite(l.rgb.x) && std::isfinite(l.rgb.y) && std::isfinite(l.rgb.z)) << what;
    ASSERT_NEAR(glm::length(l.dir), 1.0F, 1e-5F) << what;
    if (!set.black) {
      ASSERT_GT(luminance(l.rgb), 0.0) << what << " light " << l.id;
    }
    ASSERT_GE(std::min({l.rgb.x, l.rgb.y, l.rgb.z}), 0.0F) << what;
  }
}

TEST(WhiteFurnace, ConstantMapGivesPiLIrradianceWithErrorShrinkingWithN) {
  const double radiance = 2.5;
  const auto normals = fibonacciSphere(64);
  for (SamplerKind kind : kBoth) {
    double previous = std::numeric_limits<double>::infinity();
    for (std::size_t n : {16U, 256U, 4096U}) {
      const EnvMap map = EnvMap::filled(MapLayout::Sphere, 256, 128, glm::vec3(float(radiance)));
      const LightSet set = lightsFor(map, n, kind);
      const auto estimate = irradianceFromLights(set.lights, normals);
      double errorSq = 0;
      for (const glm::dvec3& e : estimate) {
        const double rel = e.y / (std::numbers::pi * radiance) - 1;
        errorSq += rel * rel;
      }
      const double rms = std::sqrt(errorSq / double(normals.size()));
      EXPECT_LT(rms, previous * 0.6) << samplerName(kind) << " N=" << n;
      previous = rms;
    }
    EXPECT_LT(previous, 0.01) << samplerName(kind) << " at N=4096";
  }
}

TEST(WhiteFurnace, LightsSumToFourPiLOnTheSphereAndTwoPiLOnTheHemisphere) {
  for (SamplerKind kind : kBoth) {
    for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
      const EnvMap map = EnvMap::filled(layout, 128, 64, glm::vec3(1.0F, 2.0F, 3.0F));
      const glm::dvec3 sum = rgbSum(lightsFor(map, 100, kind));
      const double omega = coveredSolidAngleSr(layout);
      EXPECT_NEAR(sum.x / omega, 1.0, 1e-5) << samplerName(kind) << layoutName(layout);
      EXPECT_NEAR(sum.y / omega, 2.0, 2e-5);
      EXPECT_NEAR(sum.z / omega, 3.0, 3e-5);
    }
  }
}

TEST(LightGenerator, FirstKLightsOfAnNSetHaveExactlyTheKSetsDirectionsAndIds) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 360, 90);
  const SamplingTables t = buildSamplingTables(map);
  const auto pattern = defaultSamplingPattern(map.layout);
  const LightSet all = generateLights(t, pattern.first(1000), SamplerKind::Havran);
  const LightSet some = generateLights(t, pattern.first(37), SamplerKind::Havran);
  for (std::size_t i = 0; i < some.lights.size(); ++i) {
    EXPECT_EQ(some.lights[i].id, i);
    EXPECT_EQ(some.lights[i].dir, all.lights[i].dir);
    // Each light carries luminanceSr / N (the colour is its own cell's in each set).
    EXPECT_NEAR(luminance(some.lights[i].rgb) * 37.0 / 1000.0, luminance(all.lights[i].rgb),
                1e-5 * luminance(all.lights[i].rgb));
  }
}

TEST(LightGenerator, EveryLightCarriesAnEqualShareOfLuminance) {
  const EnvMap map = testing::proceduralSky(MapLayout::Sphere, 256, 128);
  for (SamplerKind kind : kBoth) {
    const LightSet set = lightsFor(map, 300, kind);
    for (const Light& l : set.lights)
      EXPECT_NEAR(luminance(l.rgb), set.luminanceSr / 300, 1e-5 * set.luminanceSr / 300);
  }
}

TEST(HardCases, AllBlackMapKeepsDirectionsAndEmitsExactlyZeroPower) {
  for (SamplerKind kind : kBoth) {
    const EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(0));
    const LightSet set = lightsFor(map, 64, kind);
    EXPECT_TRUE(set.black);
    EXPECT_EQ(set.luminanceSr, 0.0);
    expectWellFormed(set, "black");
    for (const Light& l : set.lights) EXPECT_EQ(l.rgb, glm::vec3(0));
    // Directions follow the uniform distribution: as many lights up as down, within stratification.
    int up = 0;
    for (const Light& l : set.lights) up += l.dir.y > 0 ? 1 : 0;
    EXPECT_NEAR(up, 32, 4);
  }
}

struct HotPixelCase {
  const char* where;
  MapLayout layout;
  int x, y;
};

TEST(HardCases, SunLikeHotPixelGetsAlmostAllLightsAndTheSumsStayRight) {
  const int w = 512, hs = 256, hh = 128;
  const HotPixelCase cases[] = {
      {"zenith", MapLayout::Sphere, 100, 0},
      {"horizon", MapLayout::Hemisphere, 100, hh - 1},
      {"seam left", MapLayout::Sphere, 0, 90},
      {"seam right", MapLayout::Sphere, w - 1, 90},
      {"phi 0 polar", MapLayout::Hemisphere, 0, 40},
      {"nadir", MapLayout::Sphere, 300, hs - 1},
  };
  for (const auto& c : cases) {
    const EnvMap map = testing::hotPixelMap(c.layout, w, c.layout == MapLayout::Sphere ? hs : hh,
                                            c.x, c.y, 1e8F, 1e-3F);
    const glm::dvec3 sunDir = pixelCentreDirection(map, c.x, c.y);
    for (SamplerKind kind : kBoth) {
      const LightSet set = lightsFor(map, 1024, kind);
      const std::string what = std::string(c.where) + " " + samplerName(kind);
      expectWellFormed(set, what);
      const SamplingTables t = buildSamplingTables(map);
      const glm::dvec3 sum = rgbSum(set);
      EXPECT_NEAR(sum.x / radianceIntegralSr(map).x, 1.0, 1e-5) << what;
      // Every light that carries the sun lies within two pixel rows of it.
      int nearSun = 0;
      for (const Light& l : set.lights) {
        nearSun +=
            glm::dot(glm::dvec3(l.dir), sunDir) > std::cos(3.0 * std::numbers::pi / hs) ? 1 : 0;
      }
      EXPECT_GE(nearSun, 1020) << what;
    }
  }
}

TEST(HardCases, NanInfAndNegativePixelsCountAsZeroAndAreCounted) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1));
  map.set(3, 4, glm::vec3(std::numeric_limits<float>::quiet_NaN(), 1, 1));
  map.set(5, 6, glm::vec3(std::numeric_limits<float>::infinity()));
  map.set(7, 8, glm::vec3(-5, 1, 1));
  map.set(9, 9, glm::vec3(1, -std::numeric_limits<float>::infinity(), 1));
  const SamplingTables t = buildSamplingTables(map);
  EXPECT_EQ(t.badPixels, 4U);
  for (SamplerKind kind : kBoth) {
    const LightSet set = lightsFor(map, 256, kind);
    expectWellFormed(set, samplerName(kind));
    EXPECT_NEAR(rgbSum(set).x, radianceIntegralSr(map).x,
                1e-3 * radianceIntegralSr(map).x);  // to sampling accuracy
    EXPECT_LT(radianceIntegralSr(map).x,
              4 * std::numbers::pi);  // the bad channels really count as zero
  }
}

TEST(HardCases, LargeMapWithSunKeepsTheSkyThatFloatSumsWouldLose) {
  // 4096 x 2048 with a 1e8 sun: summed in float, a row's cumulative stops growing past the sun
  // (1e-3 is far below half an ulp of 1e8, which is 4 in float) and the sky behind the sun in that
  // row would vanish. In double each addition rounds by at most 7.5e-9: 3e-5 relative here.
  EnvMap map = testing::hotPixelMap(MapLayout::Sphere, 4096, 2048, 1000, 700, 1e8F, 1e-3F);
  const SamplingTables t = buildSamplingTables(map);
  const double skyBehindSun = t.cumulativeY(700, 4096) - t.cumulativeY(700, 1001);
  EXPECT_NEAR(skyBehindSun, 1e-3 * (4096 - 1001), 1e-4);
  const LightSet set =
      generateLights(t, defaultSamplingPattern(map.layout).first(4096), SamplerKind::Havran);
  expectWellFormed(set, "4096x2048");
  EXPECT_NEAR(rgbSum(set).y / radianceIntegralSr(map).y, 1.0, 1e-5);
}

TEST(HardCases, OneLightCarriesTheWholeMapAndSixtyFiveThousandStayFinite) {
  const EnvMap map = testing::proceduralSky(MapLayout::Sphere, 256, 128);
  const SamplingTables t = buildSamplingTables(map);
  for (SamplerKind kind : kBoth) {
    const LightSet one = lightsFor(map, 1, kind);
    ASSERT_EQ(one.lights.size(), 1U);
    EXPECT_NEAR(luminance(one.lights[0].rgb), t.luminanceSr, 1e-6 * t.luminanceSr);
    const LightSet many = lightsFor(map, kMaxLights, kind);
    ASSERT_EQ(many.lights.size(), kMaxLights);
    expectWellFormed(many, "65536");
    EXPECT_NEAR(rgbSum(many).z / radianceIntegralSr(map).z, 1.0, 1e-3);
  }
}

}  // namespace
}  // namespace vem
