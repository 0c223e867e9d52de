// Chi-square goodness of fit of a direction sampler against a density, for the samplers' tests.
// Bins are blocks of the map's pixels in (row, column) coordinates; the expected probability of a
// bin integrates the density numerically (sub-pixel midpoint rule, exact solid angles). Bins with
// fewer than 5 expected samples are pooled into one.
#pragma once

#include <functional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/sampling_tables.h"

namespace vem::testing {

struct ChiSquareResult {
  double statistic = 0.0;
  int degreesOfFreedom = 0;
  double criticalValue = 0.0;  // at the significance level asked for
  [[nodiscard]] bool passes() const { return statistic <= criticalValue; }
};

using DirectionSampler = std::function<glm::dvec3(glm::dvec2)>;
using DensitySr = std::function<double(glm::dvec3)>;

// Draws `sampleCount` iid uniform square points (fixed seed) through `sampler` and compares their
// histogram over blocks of `blockRows` x `blockColumns` pixels with `density`.
[[nodiscard]] ChiSquareResult chiSquareTest(const SamplingTables& tables,
                                            const DirectionSampler& sampler,
                                            const DensitySr& density, int sampleCount,
                                            int blockRows, int blockColumns,
                                            double significance = 1e-4);

// Integral of `density` over the map's domain (should be 1).
[[nodiscard]] double integrateDensity(const SamplingTables& tables, const DensitySr& density);

}  // namespace vem::testing
