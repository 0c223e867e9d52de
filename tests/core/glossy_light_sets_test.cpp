#include "core/glossy_light_sets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "support/random_directions.h"

namespace vem {
namespace {

constexpr double kPi = std::numbers::pi;

double radicalInverse(std::uint32_t i, std::uint32_t base) {
  double result = 0.0;
  double scale = 1.0 / base;
  for (; i > 0; i /= base, scale /= base) result += (i % base) * scale;
  return result;
}

// A progressive uniform light set: Halton (2, 3) mapped to the sphere, equal power summing to 4 pi
// (a white environment of radiance 1), so every prefix is spread over the sphere too.
LightSet haltonLights(std::uint32_t n) {
  LightSet set;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * radicalInverse(i + 1, 2);
    const double phi = 2.0 * kPi * radicalInverse(i + 1, 3);
    const double ring = std::sqrt(1.0 - y * y);
    const glm::dvec3 dir{ring * std::cos(phi), y, ring * std::sin(phi)};
    set.lights.push_back({i, glm::vec3(dir), glm::vec3(float(4.0 * kPi / n))});
  }
  set.luminanceSr = 4.0 * kPi;
  return set;
}

glm::dvec3 randomUnit(std::mt19937& rng) { return testing::randomUnitVector(rng); }

double cosineTo(glm::dvec3 r, const Light& light) {
  return glm::dot(r, glm::normalize(glm::dvec3(light.dir)));
}

// Sum over the shading lights of weight x red x lobe(R . dir).
template <class Lobe>
double glossyEstimate(glm::dvec3 r, const GlossyLightSets& sets, const GlossyRegions& regions,
                      Lobe lobe,
                      std::size_t maxConeLights = std::numeric_limits<std::size_t>::max()) {
  double sum = 0.0;
  for (const GlossyShadingLight& s : glossyLightsFor(r, sets, regions, maxConeLights)) {
    sum += s.weight * double(sets.low.lights[s.index].rgb.x) *
           lobe(cosineTo(r, sets.low.lights[s.index]));
  }
  return sum;
}

template <class Lobe>
double allOfL(glm::dvec3 r, const LightSet& low, Lobe lobe) {
  double sum = 0.0;
  for (const Light& light : low.lights) sum += double(light.rgb.x) * lobe(cosineTo(r, light));
  return sum;
}

struct Fixture {
  GlossyRegions regions = makeGlossyRegions({200, 50, 32});
  GlossyLightSets sets = makeGlossyLightSets(haltonLights(4096), 256, regions);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

TEST(GlossyLightSets, HighSetIsTheRescaledPrefixOfLow) {
  const LightSet low = haltonLights(1000);
  const LightSet high = highLightSet(low, 125);
  ASSERT_EQ(high.lights.size(), 125U);
  EXPECT_EQ(high.luminanceSr, low.luminanceSr);
  for (std::size_t k = 0; k < high.lights.size(); ++k) {
    EXPECT_EQ(high.lights[k].id, low.lights[k].id);
    EXPECT_EQ(high.lights[k].dir, low.lights[k].dir);
    EXPECT_FLOAT_EQ(high.lights[k].rgb.x, 8.0F * low.lights[k].rgb.x);
  }
}

TEST(GlossyLightSets, ConeIsHalfTheSmallestSeparationOfTheLowRegions) {
  const GlossyRegions& regions = fixture().regions;
  EXPECT_DOUBLE_EQ(regions.coneHalfAngleRad, 0.5 * minCentreSeparationRad(regions.low));
  std::cout << "S_L (50 regions) cone half-angle " << regions.coneHalfAngleRad << " rad\n";
  EXPECT_GT(regions.coneHalfAngleRad, 0.1);
  EXPECT_LT(regions.coneHalfAngleRad, 0.5);
}

TEST(GlossyLightSets, ShadingLightsAreExactlyTheTwoStrataAndNoneTwice) {
  const Fixture& f = fixture();
  const double cosHalf = std::cos(f.regions.coneHalfAngleRad);
  std::mt19937 rng(21);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 r = randomUnit(rng);
    std::set<std::uint32_t> got;
    for (const GlossyShadingLight& s : glossyLightsFor(r, f.sets, f.regions)) {
      ASSERT_TRUE(got.insert(s.index).second) << "light " << s.index << " counted twice";
      EXPECT_EQ(s.weight, s.inCone ? 1.0 : 16.0);
    }
    std::set<std::uint32_t> expected;
    for (std::uint32_t k = 0; k < f.sets.low.lights.size(); ++k) {
      const double c = cosineTo(r, f.sets.low.lights[k]);
      if (c > cosHalf || (k < f.sets.high.lights.size() && c > 0.0)) expected.insert(k);
    }
    ASSERT_EQ(got, expected) << "reflected direction " << i;
  }
}

TEST(GlossyLightSets, ConeIndicatorIntegralEqualsTheOneOfAllLights) {
  const Fixture& f = fixture();
  const double cosHalf = std::cos(f.regions.coneHalfAngleRad);
  const auto indicator = [cosHalf](double c) { return c > cosHalf ? 1.0 : 0.0; };
  std::mt19937 rng(23);
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 r = randomUnit(rng);
    EXPECT_DOUBLE_EQ(glossyEstimate(r, f.sets, f.regions, indicator),
                     allOfL(r, f.sets.low, indicator));
  }
}

TEST(GlossyLightSets, PhongLobeEstimateMatchesTheOneOfAllLights) {
  const Fixture& f = fixture();
  const auto phong = [](double c) { return c > 0.0 ? std::pow(c, 8.0) : 0.0; };
  std::mt19937 rng(25);
  double bias = 0.0;
  double meanAbs = 0.0;
  const int count = 2000;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 r = randomUnit(rng);
    const double reference = allOfL(r, f.sets.low, phong);
    const double error = glossyEstimate(r, f.sets, f.regions, phong) / reference - 1.0;
    bias += error / count;
    meanAbs += std::abs(error) / count;
  }
  std::cout << "Phong n = 8, |L| 4096, |H| 256: relative bias " << bias << ", mean |error| "
            << meanAbs << "\n";
  EXPECT_LT(std::abs(bias), 0.01);
  EXPECT_LT(meanAbs, 0.1);
}

TEST(GlossyLightSets, ConeCapKeepsTheFirstKConeLightsScaledToTheWholeCone) {
  const Fixture& f = fixture();
  const double cosHalf = std::cos(f.regions.coneHalfAngleRad);
  const auto indicator = [cosHalf](double c) { return c > cosHalf ? 1.0 : 0.0; };
  const auto phong = [](double c) { return c > 0.0 ? std::pow(c, 8.0) : 0.0; };
  std::mt19937 rng(27);
  double meanAbs = 0.0;
  const int count = 500;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 r = randomUnit(rng);
    const auto all = glossyLightsFor(r, f.sets, f.regions);
    const auto capped = glossyLightsFor(r, f.sets, f.regions, 8);
    std::vector<std::uint32_t> inCone, cappedInCone;
    for (const auto& s : all)
      if (s.inCone) inCone.push_back(s.index);
    double weightSum = 0.0;
    for (const auto& s : capped) {
      if (!s.inCone) continue;
      cappedInCone.push_back(s.index);
      weightSum += s.weight;
    }
    // The first 8 cone lights in light order (a progressive prefix), weights summing to the count.
    const std::size_t kept = std::min<std::size_t>(8, inCone.size());
    ASSERT_EQ(cappedInCone,
              std::vector<std::uint32_t>(inCone.begin(), inCone.begin() + std::ptrdiff_t(kept)));
    EXPECT_NEAR(weightSum, double(inCone.size()), 1e-9);
    EXPECT_NEAR(glossyEstimate(r, f.sets, f.regions, indicator, 8),
                allOfL(r, f.sets.low, indicator), 1e-3 * allOfL(r, f.sets.low, indicator) + 1e-9);
    meanAbs +=
        std::abs(glossyEstimate(r, f.sets, f.regions, phong, 8) / allOfL(r, f.sets.low, phong) -
                 1.0) /
        count;
  }
  std::cout << "Phong n = 8 with at most 8 cone lights: mean |error| " << meanAbs << "\n";
  EXPECT_LT(meanAbs, 0.15);
}

}  // namespace
}  // namespace vem
