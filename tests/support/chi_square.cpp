#include "support/chi_square.h"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace vem::testing {
namespace {

constexpr int kSubSamples = 6;  // per pixel side

// Probability mass of `density` over pixel (x, y) by the midpoint rule in (r, xc).
double pixelMass(const SamplingTables& t, const DensitySr& density, int x, int y) {
  double mass = 0;
  for (int j = 0; j < kSubSamples; ++j) {
    const double r0 = y + double(j) / kSubSamples;
    const double r1 = y + double(j + 1) / kSubSamples;
    // Solid angle of a sub-pixel: (1 - cos theta_max) (s1 - s0) (2 pi / W) / kSubSamples.
    const double oneMinusCosMax = t.layout == MapLayout::Sphere ? 2.0 : 1.0;
    const double omega = oneMinusCosMax * (sFromRowCoord(t, r1) - sFromRowCoord(t, r0)) *
                         (2 * std::numbers::pi / t.width) / kSubSamples;
    for (int i = 0; i < kSubSamples; ++i) {
      const double xc = x + (i + 0.5) / kSubSamples;
      mass += omega * density(directionFromMapCoords(t, 0.5 * (r0 + r1), xc));
    }
  }
  return mass;
}

// Upper quantile of chi-square with k degrees of freedom (Wilson-Hilferty), z the normal quantile.
double chiSquareQuantile(int k, double z) {
  const double a = 2.0 / (9.0 * k);
  const double c = 1 - a + z * std::sqrt(a);
  return k * c * c * c;
}

double normalUpperQuantile(double p) {
  // Bisection on the complementary error function: accurate enough for a threshold.
  double lo = 0, hi = 10;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

ChiSquareResult chiSquareTest(const SamplingTables& t, const DirectionSampler& sampler,
                              const DensitySr& density, int sampleCount, int blockRows,
                              int blockColumns, double significance) {
  const int binRows = (t.height + blockRows - 1) / blockRows;
  const int binColumns = (t.width + blockColumns - 1) / blockColumns;
  std::vector<double> expected(std::size_t(binRows * binColumns), 0.0);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      expected[std::size_t((y / blockRows) * binColumns + x / blockColumns)] +=
          sampleCount * pixelMass(t, density, x, y);
  std::vector<double> observed(expected.size(), 0.0);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < sampleCount; ++i) {
    const glm::dvec3 dir = sampler({uniform(rng), uniform(rng)});
    const MapCoords c = mapCoordsFromDirection(t, dir);
    const int y = std::min(int(c.r), t.height - 1);
    const int x = std::min(int(c.xc), t.width - 1);
    observed[std::size_t((y / blockRows) * binColumns + x / blockColumns)] += 1;
  }
  ChiSquareResult result;
  double pooledExpected = 0, pooledObserved = 0;
  int bins = 0;
  for (std::size_t b = 0; b < expected.size(); ++b) {
    if (expected[b] < 5) {
      pooledExpected += expected[b];
      pooledObserved += observed[b];
      continue;
    }
    const double d = observed[b] - expected[b];
    result.statistic += d * d / expected[b];
    ++bins;
  }
  if (pooledExpected > 0) {
    const double d = pooledObserved - pooledExpected;
    result.statistic += d * d / std::max(pooledExpected, 1e-9);
    ++bins;
  }
  result.degreesOfFreedom = std::max(1, bins - 1);
  result.criticalValue =
      chiSquareQuantile(result.degreesOfFreedom, normalUpperQuantile(significance));
  return result;
}

double integrateDensity(const SamplingTables& t, const DensitySr& density) {
  double total = 0;
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x) total += pixelMass(t, density, x, y);
  return total;
}

}  // namespace vem::testing
