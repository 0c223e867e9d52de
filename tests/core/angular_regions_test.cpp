#include "core/angular_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "core/cube_map_lookup.h"

#include "support/random_directions.h"

namespace vem {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 randomUnit(std::mt19937& rng) { return testing::randomUnitVector(rng); }

LightSet randomLights(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  LightSet set;
  for (int i = 0; i < n; ++i) {
    set.lights.push_back({std::uint32_t(i), glm::vec3(randomUnit(rng)), glm::vec3(1.0F)});
  }
  return set;
}

double angleRad(glm::dvec3 a, glm::dvec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(CubeMapLookup, AxesMapToTheCentresOfTheirFaces) {
  const std::pair<glm::dvec3, CubeFace> cases[] = {
      {{1, 0, 0}, CubeFace::PosX},  {{-1, 0, 0}, CubeFace::NegX}, {{0, 1, 0}, CubeFace::PosY},
      {{0, -1, 0}, CubeFace::NegY}, {{0, 0, 1}, CubeFace::PosZ},  {{0, 0, -1}, CubeFace::NegZ}};
  for (const auto& [dir, face] : cases) {
    const CubeFaceCoord coord = cubeFaceCoordOf(dir);
    EXPECT_EQ(coord.face, face);
    EXPECT_DOUBLE_EQ(coord.s, 0.5);
    EXPECT_DOUBLE_EQ(coord.t, 0.5);
    EXPECT_EQ(cubeTexelOf(dir, 4), (CubeTexel{face, 2, 2}));
  }
}

TEST(CubeMapLookup, FaceAxesFollowTheOpenGlTable) {
  // +X: sc = -z, tc = -y.  +Y: sc = +x, tc = +z.  -Y: tc = -z.  -Z: sc = -x.
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({1, 0, -0.5}).s, 0.75);
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({1, -0.5, 0}).t, 0.75);
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({0.5, 1, 0}).s, 0.75);
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({0, 1, 0.5}).t, 0.75);
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({0, -1, 0.5}).t, 0.25);
  EXPECT_DOUBLE_EQ(cubeFaceCoordOf({0.5, 0, -1}).s, 0.25);
}

TEST(CubeMapLookup, TexelCentresRoundTripAtEdgesAndCorners) {
  for (int faceSize : {1, 2, 7, 32}) {
    for (std::size_t index = 0; index < cubeTexelCount(faceSize); ++index) {
      const CubeTexel texel = cubeTexelFromIndex(index, faceSize);
      ASSERT_EQ(cubeTexelIndex(texel, faceSize), index);
      const glm::dvec3 dir = cubeTexelCentreDirection(texel, faceSize);
      ASSERT_NEAR(glm::length(dir), 1.0, 1e-12);
      ASSERT_EQ(cubeTexelOf(dir, faceSize), texel)
          << "F " << faceSize << ", face " << int(texel.face) << ", texel " << texel.column << ","
          << texel.row;
    }
  }
}

TEST(CubeMapLookup, FaceCoordinatesRoundTripForRandomDirections) {
  std::mt19937 rng(3);
  for (int i = 0; i < 10000; ++i) {
    const glm::dvec3 dir = randomUnit(rng);
    EXPECT_LT(glm::distance(directionFromCubeFaceCoord(cubeFaceCoordOf(dir)), dir), 1e-12);
  }
}

TEST(CubeMapLookup, TexelRadiusCoversEveryDirectionInsideTheTexel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int faceSize = 8;
  for (std::size_t index = 0; index < cubeTexelCount(faceSize); ++index) {
    const CubeTexel texel = cubeTexelFromIndex(index, faceSize);
    const glm::dvec3 centre = cubeTexelCentreDirection(texel, faceSize);
    const double radius = cubeTexelRadiusRad(texel, faceSize);
    for (int k = 0; k < 50; ++k) {
      const CubeFaceCoord inside{texel.face, (texel.column + unit(rng)) / faceSize,
                                 (texel.row + unit(rng)) / faceSize};
      EXPECT_LE(angleRad(centre, directionFromCubeFaceCoord(inside)), radius + 1e-12);
    }
  }
}

TEST(AngularRegions, EveryNormalLiesWithinTheRadiusOfItsRegion) {
  const AngularRegions regions = makeAngularRegions();
  std::mt19937 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 n = randomUnit(rng);
    const std::uint32_t region = regions.regionOf(n);
    ASSERT_LT(region, regions.count());
    EXPECT_LE(angleRad(regions.centres[region], n), regions.radiusRad[region]);
  }
}

TEST(AngularRegions, EveryLightThatReachesANormalIsInTheListOfItsRegion) {
  const AngularRegions regions = makeAngularRegions();
  const LightSet set = randomLights(1000, 9);
  const RegionLightLists lists = visibleLightLists(regions, set);
  std::mt19937 rng(11);
  for (int i = 0; i < 5000; ++i) {
    const glm::dvec3 n = randomUnit(rng);
    const auto list = lists.lightsOf(regions.regionOf(n));
    std::vector<bool> listed(set.lights.size(), false);
    for (std::uint32_t k : list) listed[k] = true;
    for (std::size_t k = 0; k < set.lights.size(); ++k) {
      if (glm::dot(n, glm::dvec3(set.lights[k].dir)) > 0.0) {
        ASSERT_TRUE(listed[k]) << "normal " << i << " misses light " << k;
      }
    }
  }
}

TEST(AngularRegions, ListsAreMuchShorterThanTheLightCount) {
  const AngularRegions regions = makeAngularRegions();
  const LightSet set = randomLights(4096, 13);
  const double fraction = visibleLightLists(regions, set).meanFraction(set.lights.size());
  std::cout << "mean region list fraction " << fraction << " (speed-up " << 1.0 / fraction
            << "), largest region radius "
            << *std::max_element(regions.radiusRad.begin(), regions.radiusRad.end()) << " rad\n";
  // Half the lights is the bound for a normal (b = pi / 2); the paper reports 1.6 - 1.8.
  EXPECT_GT(fraction, 0.5);
  EXPECT_LT(fraction, 0.65);
}

TEST(AngularRegions, ListsKeepLightOrderSoPrefixesStayProgressive) {
  const AngularRegions regions = makeAngularRegions(60, 16);
  const LightSet set = randomLights(800, 15);
  const RegionLightLists lists = visibleLightLists(regions, set);
  LightSet prefix = set;
  prefix.lights.resize(200);
  const RegionLightLists prefixLists = visibleLightLists(regions, prefix);
  for (std::uint32_t region = 0; region < regions.count(); ++region) {
    const auto full = lists.lightsOf(region);
    EXPECT_TRUE(std::is_sorted(full.begin(), full.end()));
    const auto head = prefixLists.lightsOf(region);
    ASSERT_LE(head.size(), full.size());
    EXPECT_TRUE(std::equal(head.begin(), head.end(), full.begin())) << "region " << region;
  }
}

}  // namespace
}  // namespace vem
