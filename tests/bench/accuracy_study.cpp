#include "accuracy_study.h"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench_fixtures.h"
#include "core/default_pattern.h"
#include "core/irradiance.h"
#include "core/sampling_pattern.h"
#include "core/sphere_points.h"
#include "core/upper_hemisphere.h"
#include "support/test_maps.h"

namespace vem::bench {
namespace {

double errorOf(const SamplingTables& tables, std::span<const glm::dvec2> pattern,
               SamplerKind kind, const std::vector<glm::dvec3>& reference) {
  static const auto normals = fibonacciSphere(64);
  const LightSet lights = generateLights(tables, pattern, kind);
  return relativeRmsError(irradianceFromLights(lights.lights, normals), reference);
}

EnvMap inLayout(const EnvMap& equirect, MapLayout layout) {
  return layout == MapLayout::Sphere ? equirect : upperHemisphere(equirect);
}

}  // namespace

std::vector<MapErrors> perMapErrors(const std::vector<std::size_t>& counts, MapLayout layout) {
  const auto normals = fibonacciSphere(64);
  std::vector<MapErrors> rows;
  for (const auto& [name, equirect] : sharedHdris()) {
    const EnvMap map = inLayout(equirect, layout);
    const SamplingTables tables = buildSamplingTables(map);
    const auto reference = irradianceFromMap(map, normals);
    MapErrors row{name, {}, {}};
    for (std::size_t n : counts) {
      const auto pattern = defaultSamplingPattern(layout).first(n);
      row.havran.push_back(errorOf(tables, pattern, SamplerKind::Havran, reference));
      row.standard.push_back(errorOf(tables, pattern, SamplerKind::Standard, reference));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<PatternErrors> patternComparison(const std::vector<std::size_t>& counts) {
  const std::size_t most = *std::max_element(counts.begin(), counts.end());
  LloydOptions square;
  square.domain = RelaxationDomain::Square;
  const auto surface = defaultSamplingPattern(MapLayout::Sphere);
  const std::vector<std::pair<std::string, std::vector<glm::dvec2>>> patterns{
      {"Halton (no relaxation)", haltonPoints(most)},
      {"Halton + Lloyd in the square", relaxedHaltonPattern(most, square)},
      {"Halton + Lloyd on the sphere (default)",
       {surface.begin(), surface.begin() + std::ptrdiff_t(most)}}};
  const auto normals = fibonacciSphere(64);
  std::vector<PatternErrors> result;
  for (const auto& [name, points] : patterns) {
    PatternErrors row{name, std::vector<double>(counts.size(), 0.0),
                      std::vector<double>(counts.size(), 0.0)};
    for (const auto& [mapName, map] : sharedHdris()) {
      const SamplingTables tables = buildSamplingTables(map);
      const auto reference = irradianceFromMap(map, normals);
      for (std::size_t k = 0; k < counts.size(); ++k) {
        const std::span<const glm::dvec2> pattern(points.data(), counts[k]);
        const double maps = double(sharedHdris().size());
        row.havranMean[k] += errorOf(tables, pattern, SamplerKind::Havran, reference) / maps;
        row.standardMean[k] +=
            errorOf(tables, pattern, SamplerKind::Standard, reference) / maps;
      }
    }
    result.push_back(std::move(row));
  }
  return result;
}

void registerAccuracyTimingBenchmarks(const std::vector<std::size_t>& counts) {
  for (SamplerKind kind : {SamplerKind::Havran, SamplerKind::Standard}) {
    for (std::size_t n : counts) {
      benchmark::RegisterBenchmark(
          fmt::format("accuracy/{}/{}", samplerName(kind), n).c_str(),
          [kind, n](benchmark::State& s) {
            const auto& maps = sharedHdris();
            SamplingTables tables;
            std::size_t next = 0;
            for (auto _ : s) {
              const EnvMap& map = maps[next++ % maps.size()].map;
              tables = buildSamplingTables(map, std::move(tables));
              benchmark::DoNotOptimize(
                  generateLights(tables, defaultSamplingPattern(map.layout).first(n), kind));
            }
          })
          ->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace vem::bench
