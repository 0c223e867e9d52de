// Havran's inverse transform: round trips, bijectivity, continuity (diagonals, seam, pole,
// equator), chi-square against its own density, and the standard sampler's row jumps it avoids;
// the standard sampler's round trip and density.
#include "core/havran_sampler.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/sampling_tables.h"
#include "core/standard_sampler.h"
#include "support/chi_square.h"
#include "support/test_maps.h"

namespace vem {
namespace {

double angleRad(glm::dvec3 a, glm::dvec3 b) {
  return 2 * std::asin(std::min(1.0, 0.5 * glm::length(a - b)));
}

struct NamedMap {
  const char* name;
  EnvMap map;
};

std::vector<NamedMap> testMaps() {
  std::vector<NamedMap> maps;
  for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
    const int h = layout == MapLayout::Sphere ? 32 : 16;
    maps.push_back({"uniform", EnvMap::filled(layout, 64, h, glm::vec3(1))});
    maps.push_back({"sky", testing::proceduralSky(layout, 64, h)});
    maps.push_back({"hot pixel", testing::hotPixelMap(layout, 64, h, 20, h / 3, 1e8F, 1e-3F)});
  }
  return maps;
}

std::vector<glm::dvec2> randomSquarePoints(int count, double margin) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(margin, 1 - margin);
  std::vector<glm::dvec2> points(static_cast<std::size_t>(count));
  for (auto& p : points) p = {uniform(rng), uniform(rng)};
  return points;
}

TEST(HavranSampler, SquareToDirectionToSquareRoundTripsOnEveryMap) {
  for (const auto& [name, map] : testMaps()) {
    const SamplingTables t = buildSamplingTables(map);
    double worst = 0;
    for (glm::dvec2 p : randomSquarePoints(4000, 1e-3)) {
      if (glm::length(p - glm::dvec2(0.5)) < 1e-3) continue;  // the pole: every angle is the zenith
      worst = std::max(worst, glm::length(havranSquare(t, havranSample(t, p).dir) - p));
    }
    EXPECT_LT(worst, 1e-7) << name << " " << layoutName(map.layout);
  }
}

TEST(HavranSampler, DirectionToSquareToDirectionRoundTripsSoTheMapIsOnto) {
  for (const auto& [name, map] : testMaps()) {
    const SamplingTables t = buildSamplingTables(map);
    std::mt19937_64 rng(3);
    std::normal_distribution<double> normal;
    double worst = 0;
    for (int i = 0; i < 4000; ++i) {
      glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
      if (map.layout == MapLayout::Hemisphere) d.y = std::abs(d.y);
      worst = std::max(worst, angleRad(havranSample(t, havranSquare(t, d)).dir, d));
    }
    EXPECT_LT(worst, 1e-6) << name << " " << layoutName(map.layout);
  }
}

// Pairs of square points `step` apart straddling a line; returns the largest angle between images.
template <class Sampler>
double worstAngleAcross(const SamplingTables& t, Sampler sample, glm::dvec2 from, glm::dvec2 to,
                        glm::dvec2 across, double step) {
  double worst = 0;
  for (int i = 1; i < 400; ++i) {
    const glm::dvec2 p = from + (to - from) * (i / 400.0);
    worst = std::max(worst, angleRad(sample(t, p - 0.5 * step * across).dir,
                                     sample(t, p + 0.5 * step * across).dir));
  }
  return worst;
}

TEST(HavranSampler, StaysContinuousAcrossDiagonalsSeamAndEquator) {
  const glm::dvec2 diagonal = glm::normalize(glm::dvec2(1, -1));
  for (const auto& [name, map] : testMaps()) {
    if (std::string(name) == "hot pixel") continue;  // Lipschitz constant ~1e5 there; see below
    const SamplingTables t = buildSamplingTables(map);
    const auto lines = {
        std::tuple{glm::dvec2(0.51, 0.51), glm::dvec2(0.99, 0.99), diagonal},  // diagonal
        std::tuple{glm::dvec2(0.01, 0.99), glm::dvec2(0.49, 0.51), diagonal * -1.0},
        std::tuple{glm::dvec2(0.51, 0.5), glm::dvec2(0.99, 0.5), glm::dvec2(0, 1)},  // psi = 0 seam
        std::tuple{glm::dvec2(0.5, 0.02), glm::dvec2(0.98, 0.5), glm::dvec2(1, 1) / std::sqrt(2.0)},
    };
    for (const auto& [from, to, across] : lines) {
      const double step = 1e-4;
      const double worst = worstAngleAcross(t, havranSample, from, to, across, step);
      EXPECT_LT(worst, 60 * step) << name << " " << layoutName(map.layout);
      // A jump stays large however close the points: shrinking the step must shrink the angle.
      EXPECT_LT(worstAngleAcross(t, havranSample, from, to, across, step * 1e-3), 60 * step * 1e-3)
          << name << " " << layoutName(map.layout);
    }
  }
}

TEST(HavranSampler, StaysContinuousOverAHotPixelOfEightOrdersOfMagnitude) {
  const EnvMap map = testing::hotPixelMap(MapLayout::Sphere, 64, 32, 20, 10, 1e8F, 1e-3F);
  const SamplingTables t = buildSamplingTables(map);
  // Steep (the dim sky holds 1e-6 of the square) but no jump: the angle shrinks with the step.
  for (glm::dvec2 p : randomSquarePoints(300, 0.01)) {
    const glm::dvec2 offset(0.7e-9, 0.7e-9);
    EXPECT_LT(angleRad(havranSample(t, p).dir, havranSample(t, p + offset).dir), 1e-2);
  }
}

// standardSquare is standardSample's inverse (the point of the square a direction comes from):
// pbrt's rule, each warp beside its inverse, tested by the round trip.
TEST(StandardSampler, SquareToDirectionToSquareRoundTripsOnEveryMap) {
  for (const auto& [name, map] : testMaps()) {
    const SamplingTables t = buildSamplingTables(map);
    double worst = 0;
    for (glm::dvec2 p : randomSquarePoints(4000, 1e-3)) {
      worst = std::max(worst, glm::length(standardSquare(t, standardSample(t, p).dir) - p));
    }
    EXPECT_LT(worst, 1e-7) << name << " " << layoutName(map.layout);
  }
}

TEST(StandardSampler, JumpsAcrossRowBoundariesWhichIsWhatHavransMethodFixes) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 64, 16);
  const SamplingTables t = buildSamplingTables(map);
  // Crossing a row boundary in u with v fixed changes the conditional table at once.
  double worst = 0;
  for (int y = 1; y < t.height; ++y) {
    const double u = t.boxCdf[std::size_t(y)] / t.totalMass;
    worst = std::max(worst, worstAngleAcross(t, standardSample, glm::dvec2(u, 0.02),
                                             glm::dvec2(u, 0.98), glm::dvec2(1, 0), 1e-9));
  }
  EXPECT_GT(worst, 1e-3);
}

TEST(HavranSampler, DensityIntegratesToOneAndMatchesItsSamplesByChiSquare) {
  for (const auto& [name, map] : testMaps()) {
    const SamplingTables t = buildSamplingTables(map);
    const auto density = [&](glm::dvec3 d) { return havranPdfSr(t, d); };
    EXPECT_NEAR(testing::integrateDensity(t, density), 1.0, 2e-3) << name;
    const auto result = testing::chiSquareTest(
        t, [&](glm::dvec2 p) { return havranSample(t, p).dir; }, density, 400000, 2, 4);
    EXPECT_TRUE(result.passes()) << name << " " << layoutName(map.layout) << ": chi2 "
                                 << result.statistic << " > " << result.criticalValue << " (dof "
                                 << result.degreesOfFreedom << ")";
  }
}

TEST(StandardSampler, DensityIsTheMapsImportanceAndMatchesItsSamplesByChiSquare) {
  for (const auto& [name, map] : testMaps()) {
    const SamplingTables t = buildSamplingTables(map);
    const auto density = [&](glm::dvec3 d) { return standardPdfSr(t, d); };
    EXPECT_NEAR(testing::integrateDensity(t, density), 1.0, 1e-9) << name;
    const auto result = testing::chiSquareTest(
        t, [&](glm::dvec2 p) { return standardSample(t, p).dir; }, density, 400000, 2, 4);
    EXPECT_TRUE(result.passes()) << name << ": chi2 " << result.statistic << " > "
                                 << result.criticalValue;
  }
}

TEST(HavranSampler, ChiSquareRejectsADensityThatIsNotTheSamplers) {
  // The test above can fail: Havran's samples against the standard sampler's (unblended) density
  // on a map with strong row-to-row contrast.
  const EnvMap map = testing::proceduralSky(MapLayout::Sphere, 64, 32);
  const SamplingTables t = buildSamplingTables(map);
  const auto result = testing::chiSquareTest(
      t, [&](glm::dvec2 p) { return havranSample(t, p).dir; },
      [&](glm::dvec3 d) { return standardPdfSr(t, d); }, 400000, 1, 1);
  EXPECT_FALSE(result.passes()) << result.statistic << " <= " << result.criticalValue;
}

}  // namespace
}  // namespace vem
