#include "core/light_clustering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <vector>

#include "core/sphere_points.h"

namespace vem {
namespace {

constexpr double kPi = std::numbers::pi;

// n lights uniform over the sphere, id = index, rgb a dyadic value (k / 64) so sums are exact.
LightSet randomLights(int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> level(0, 64);
  LightSet set;
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * unit(rng);
    const double phi = 2.0 * kPi * unit(rng);
    const double ring = std::sqrt(1.0 - y * y);
    const glm::dvec3 dir{ring * std::cos(phi), y, ring * std::sin(phi)};
    const glm::vec3 rgb{float(level(rng)) / 64.0F, float(level(rng)) / 64.0F,
                        float(level(rng)) / 64.0F};
    set.lights.push_back({std::uint32_t(i), glm::vec3(dir), rgb});
  }
  set.luminanceSr = 12.5;
  return set;
}

glm::dvec3 unitDir(const Light& light) { return glm::normalize(glm::dvec3(light.dir)); }

bool within(const Light& a, const Light& b, double radiusRad) {
  return radiusRad >= kPi || glm::dot(unitDir(a), unitDir(b)) >= std::cos(radiusRad);
}

// The O(N^2) greedy reference: lives only here, to check the kd-tree search.
std::vector<std::uint32_t> bruteForceMembership(const LightSet& set, double radiusRad) {
  const std::uint32_t none = ~std::uint32_t(0);
  std::vector<std::uint32_t> owner(set.lights.size(), none);
  std::uint32_t clusters = 0;
  for (std::size_t seed = 0; seed < set.lights.size(); ++seed) {
    if (owner[seed] != none) continue;
    owner[seed] = clusters;
    for (std::size_t k = seed + 1; k < set.lights.size(); ++k) {
      if (owner[k] == none && within(set.lights[seed], set.lights[k], radiusRad))
        owner[k] = clusters;
    }
    ++clusters;
  }
  return owner;
}

glm::dvec3 rgbSum(const LightSet& set) {
  glm::dvec3 sum{0.0};
  for (const Light& light : set.lights) sum += glm::dvec3(light.rgb);
  return sum;
}

TEST(ClusterRadius, HemisphereIsThePaperFormulaAndSphereCoversFourPi) {
  EXPECT_DOUBLE_EQ(clusterRadiusRad({72, 1.85, MapLayout::Hemisphere}),
                   1.85 * std::asin(std::sqrt(2.0 / 72.0)));
  EXPECT_DOUBLE_EQ(clusterRadiusRad({72, 1.85, MapLayout::Sphere}),
                   1.85 * std::asin(std::sqrt(4.0 / 72.0)));
  EXPECT_DOUBLE_EQ(clusterRadiusRad({5, 1.85, MapLayout::Sphere}),
                   1.85 * std::asin(std::sqrt(4.0 / 5.0)));
}

TEST(ClusterRadius, BudgetWhoseDiscCoversTheWholeMapTakesEveryDirection) {
  EXPECT_DOUBLE_EQ(clusterRadiusRad({1, 1.85, MapLayout::Sphere}), kPi);
  EXPECT_DOUBLE_EQ(clusterRadiusRad({4, 1.85, MapLayout::Sphere}), kPi);
  EXPECT_DOUBLE_EQ(clusterRadiusRad({1, 1.85, MapLayout::Hemisphere}), kPi);
  EXPECT_DOUBLE_EQ(clusterRadiusRad({2, 1.85, MapLayout::Hemisphere}), kPi);
  EXPECT_LT(clusterRadiusRad({3, 1.85, MapLayout::Hemisphere}), kPi);
}

TEST(LightClustering, LargeBudgetKeepsEveryLightASingleton) {
  LightSet set;
  const std::vector<glm::dvec3> points = fibonacciSphere(64);
  for (std::uint32_t i = 0; i < 64; ++i)
    set.lights.push_back({i + 100, glm::vec3(points[i]), {1, 2, 3}});
  const Clustering out = clusterLights(set, {1000000, 1.85, MapLayout::Sphere});
  ASSERT_EQ(out.clusters.lights.size(), 64U);
  for (std::uint32_t i = 0; i < 64; ++i) {
    EXPECT_EQ(out.clusterOfLight[i], i);
    EXPECT_EQ(out.clusters.lights[i].id, i + 100);
    EXPECT_EQ(out.clusters.lights[i].rgb, set.lights[i].rgb);
    EXPECT_LT(glm::distance(glm::dvec3(out.clusters.lights[i].dir), points[i]), 1e-6);
  }
}

TEST(LightClustering, BudgetOfOneMakesOneClusterWithThePowerSummed) {
  const LightSet set = randomLights(300, 7);
  const Clustering out = clusterLights(set, {1, 1.85, MapLayout::Sphere});
  ASSERT_EQ(out.clusters.lights.size(), 1U);
  EXPECT_EQ(out.clusters.lights[0].id, 0U);
  EXPECT_EQ(glm::dvec3(out.clusters.lights[0].rgb), rgbSum(set));
  for (std::uint32_t owner : out.clusterOfLight) EXPECT_EQ(owner, 0U);
  EXPECT_EQ(out.clusters.luminanceSr, set.luminanceSr);
}

TEST(LightClustering, PowersSumExactlyPerChannel) {
  for (int budget : {4, 30, 72, 500}) {
    const LightSet set = randomLights(2000, 11);
    const Clustering out = clusterLights(set, {budget, 1.85, MapLayout::Sphere});
    EXPECT_EQ(rgbSum(out.clusters), rgbSum(set)) << "Q = " << budget;
  }
}

TEST(LightClustering, EveryMemberLiesWithinTheRadiusOfItsSeed) {
  const LightSet set = randomLights(3000, 13);
  const ClusteringParams params{72, 1.85, MapLayout::Sphere};
  const double radius = clusterRadiusRad(params);
  const Clustering out = clusterLights(set, params);
  for (std::size_t k = 0; k < set.lights.size(); ++k) {
    const Light& seed = set.lights[out.clusters.lights[out.clusterOfLight[k]].id];
    EXPECT_TRUE(within(seed, set.lights[k], radius)) << "light " << k;
    EXPECT_EQ(out.clusterOfLight[seed.id], out.clusterOfLight[k]);
  }
}

TEST(LightClustering, ClustersFollowSeedOrderAndRepeatExactly) {
  const LightSet set = randomLights(3000, 17);
  const Clustering out = clusterLights(set, {40, 1.85, MapLayout::Sphere});
  std::uint32_t nextCluster = 0;
  for (std::size_t k = 0; k < set.lights.size(); ++k) {
    if (out.clusterOfLight[k] < nextCluster) continue;
    ASSERT_EQ(out.clusterOfLight[k], nextCluster) << "cluster seeded out of order at light " << k;
    EXPECT_EQ(out.clusters.lights[nextCluster].id, set.lights[k].id);
    ++nextCluster;
  }
  EXPECT_EQ(nextCluster, out.clusters.lights.size());
  const Clustering again = clusterLights(set, {40, 1.85, MapLayout::Sphere});
  EXPECT_EQ(again.clusterOfLight, out.clusterOfLight);
  for (std::size_t c = 0; c < out.clusters.lights.size(); ++c) {
    EXPECT_EQ(again.clusters.lights[c].dir, out.clusters.lights[c].dir);
  }
}

TEST(LightClustering, AntipodalMembersFallBackToTheSeedDirection) {
  LightSet set;
  const glm::vec3 axes[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (std::uint32_t i = 0; i < 6; ++i) set.lights.push_back({i, axes[i], glm::vec3(1.0F)});
  const Clustering out = clusterLights(set, {1, 1.85, MapLayout::Sphere});
  ASSERT_EQ(out.clusters.lights.size(), 1U);
  const glm::vec3 dir = out.clusters.lights[0].dir;
  EXPECT_TRUE(std::isfinite(dir.x) && std::isfinite(dir.y) && std::isfinite(dir.z));
  EXPECT_EQ(dir, axes[0]);
}

TEST(LightClustering, KdTreeSearchMatchesTheBruteForceGreedyOnRandomSets) {
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    const LightSet set = randomLights(1500, seed);
    for (double radius : {0.0, 0.05, 0.3, 1.0, 2.5, kPi}) {
      const Clustering out = clusterLightsWithinRadius(set, radius);
      EXPECT_EQ(out.clusterOfLight, bruteForceMembership(set, radius))
          << "seed " << seed << ", e = " << radius;
    }
  }
}

TEST(LightClustering, SixtyFiveThousandLightsRunWithoutQuadraticSearch) {
  const LightSet set = randomLights(65536, 23);
  const Clustering out = clusterLights(set, {72, 1.85, MapLayout::Sphere});
  EXPECT_EQ(out.clusterOfLight.size(), set.lights.size());
  // Seeds lie more than e apart, so their count is bounded by a packing of discs of radius e / 2.
  EXPECT_GT(out.clusters.lights.size(), 36U);
  EXPECT_LT(out.clusters.lights.size(), 4U * 72U);
  EXPECT_EQ(rgbSum(out.clusters), rgbSum(set));
}

}  // namespace
}  // namespace vem
