// Accuracy figures for the report: irradiance error of the lights against exact integration over
// the shared HDRIs (64 Fibonacci normals, relative RMS, irradiance.h), per map and per N, for both
// samplers; and the same for three sampling patterns (Halton, Lloyd in the square, Lloyd on the
// surface), to show what the relaxation buys.
#pragma once

#include <string>
#include <vector>

#include "core/light_generator.h"

namespace vem::bench {

struct MapErrors {
  std::string map;
  std::vector<double> havran;    // per N of the request
  std::vector<double> standard;  // per N of the request
};

// Relative RMS irradiance error on every shared HDRI, for each N (both samplers, default pattern).
[[nodiscard]] std::vector<MapErrors> perMapErrors(const std::vector<std::size_t>& counts,
                                                  MapLayout layout);

struct PatternErrors {
  std::string pattern;
  std::vector<double> havranMean;
  std::vector<double> standardMean;
};
[[nodiscard]] std::vector<PatternErrors> patternComparison(const std::vector<std::size_t>& counts);

// Registers "accuracy/<sampler>/<N>": shared-HDRI tables plus N lights, cycling over the maps.
void registerAccuracyTimingBenchmarks(const std::vector<std::size_t>& counts);

}  // namespace vem::bench
