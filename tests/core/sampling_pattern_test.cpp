// The sampling pattern: Halton values, the embedded pattern equals the generator's output, its
// prefixes are progressive, and the relaxation really spreads points (blue noise) on the surface.
#include "core/sampling_pattern.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/default_pattern.h"
#include "core/surface_parameterization.h"

namespace vem {
namespace {

TEST(Halton, FirstPointsAreTheRadicalInversesInBasesTwoAndThree) {
  EXPECT_EQ(haltonPoint(0), glm::dvec2(0.5, 1.0 / 3));
  EXPECT_EQ(haltonPoint(1), glm::dvec2(0.25, 2.0 / 3));
  EXPECT_NEAR(haltonPoint(2).y, 1.0 / 9, 1e-15);
  EXPECT_EQ(radicalInverse(2, 6), 0.375);
}

TEST(SamplingPattern, EmbeddedPatternIsTheGeneratorsOutputBitForBit) {
  for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
    LloydOptions options;
    options.layout = layout;
    const auto fresh = relaxedHaltonPattern(1024, options);
    const auto embedded = defaultSamplingPattern(layout);
    for (std::size_t i = 0; i < fresh.size(); ++i) ASSERT_EQ(fresh[i], embedded[i]) << i;
  }
}

TEST(SamplingPattern, ShorterPatternIsAPrefixOfTheLongerOne) {
  const auto small = relaxedHaltonPattern(256);
  const auto large = relaxedHaltonPattern(2048);
  for (std::size_t i = 0; i < small.size(); ++i) ASSERT_EQ(small[i], large[i]) << i;
}

TEST(SamplingPattern, PointsStayInsideTheSquare) {
  for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
    for (const glm::dvec2& p : defaultSamplingPattern(layout)) {
      ASSERT_TRUE(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1) << p.x << " " << p.y;
    }
  }
}

struct Spacing {
  double minimum = 10;  // smallest distance between two points
  double mean = 0;      // mean distance to the nearest neighbour
};

// Chordal distances between the first n points on the surface, relative to the ideal spacing.
Spacing normalisedSpacing(const std::vector<glm::dvec2>& square, std::size_t n, MapLayout layout) {
  std::vector<glm::dvec3> dirs(n);
  for (std::size_t i = 0; i < n; ++i)
    dirs[i] = surfaceDirection(layout, cylinderFromSquare(layout, square[i]));
  Spacing spacing;
  for (std::size_t i = 0; i < n; ++i) {
    double nearest = 10;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) nearest = std::min(nearest, glm::length(dirs[i] - dirs[j]));
    spacing.minimum = std::min(spacing.minimum, nearest);
    spacing.mean += nearest / double(n);
  }
  const double ideal = std::sqrt(coveredSolidAngleSr(layout) / double(n));
  return {spacing.minimum / ideal, spacing.mean / ideal};
}

TEST(SamplingPattern, RelaxationSpreadsPointsFartherApartThanHaltonOnTheSurface) {
  for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
    const auto pattern = defaultSamplingPattern(layout);
    const std::vector<glm::dvec2> relaxed(pattern.begin(), pattern.begin() + 1024);
    const auto halton = haltonPoints(1024);
    for (std::size_t n : {64U, 256U, 1024U}) {
      const Spacing r = normalisedSpacing(relaxed, n, layout);
      const Spacing h = normalisedSpacing(halton, n, layout);
      std::printf("%s N=%zu min %.3f vs Halton %.3f, mean nearest %.3f vs %.3f\n",
                  layoutName(layout), n, r.minimum, h.minimum, r.mean, h.mean);
      EXPECT_GT(r.minimum, 1.1 * h.minimum) << layoutName(layout) << " N=" << n;
      EXPECT_GT(r.mean, 1.1 * h.mean) << layoutName(layout) << " N=" << n;
    }
  }
}

}  // namespace
}  // namespace vem
