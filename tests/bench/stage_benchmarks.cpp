// Per-stage timings of the light pipeline (single-threaded), registered by name so the report can
// place them in its table: "stage/<stage>/<config index>".
#include "stage_benchmarks.h"

#include <algorithm>
#include <functional>
#include <numeric>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench_fixtures.h"
#include "client/render/shadow_groups.h"
#include "core/angular_regions.h"
#include "core/default_pattern.h"
#include "core/light_clustering.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "core/temporal_filter.h"
#include "support/test_maps.h"

namespace vem::bench {
namespace {

struct Pipeline {
  EnvMap map;
  SamplingTables tables;
  LightSet lights;
  AngularRegions regions = makeAngularRegions();
  ClusteringParams clustering{72, kDefaultClusterCorrectionFactor, MapLayout::Hemisphere};

  explicit Pipeline(const StageConfig& c)
      : map(testing::proceduralSky(MapLayout::Hemisphere, c.width, c.height)),
        tables(buildSamplingTables(map)),
        lights(generateLights(tables, defaultSamplingPattern(map.layout).first(c.lights),
                              SamplerKind::Havran)) {}
};

void registerStage(const std::string& stage, std::size_t index,
                   std::function<void(benchmark::State&)> body) {
  benchmark::RegisterBenchmark(fmt::format("stage/{}/{}", stage, index).c_str(), body)
      ->Unit(benchmark::kMicrosecond)
      ->ComputeStatistics("min", [](const std::vector<double>& v) {
        return *std::min_element(v.begin(), v.end());
      });
}

}  // namespace

void registerStageBenchmarks() {
  const auto& configs = stageConfigs();
  for (std::size_t i = 0; i < configs.size(); ++i) {
    auto p = std::make_shared<Pipeline>(configs[i]);
    const auto pattern = defaultSamplingPattern(MapLayout::Hemisphere).first(configs[i].lights);
    registerStage("tables", i, [p](benchmark::State& s) {
      for (auto _ : s) p->tables = buildSamplingTables(p->map, std::move(p->tables));
    });
    for (SamplerKind kind : {SamplerKind::Havran, SamplerKind::Standard}) {
      // As vemd does: the cells built once per light count, outside the loop.
      const auto cells =
          std::make_shared<const LightCells>(lightCellsFor(MapLayout::Hemisphere, pattern, kind));
      registerStage(std::string("lights_") + samplerName(kind), i,
                    [p, pattern, kind, cells](benchmark::State& s) {
                      for (auto _ : s)
                        benchmark::DoNotOptimize(generateLights(p->tables, pattern, kind, *cells));
                    });
    }
    registerStage("fir", i, [p](benchmark::State& s) {
      TemporalFilter filter(presetTaps(FilterPreset::Paper9));
      std::uint64_t seq = 0;
      for (auto _ : s) benchmark::DoNotOptimize(filter.push(seq++, p->lights));
    });
    registerStage("clustering", i, [p](benchmark::State& s) {
      for (auto _ : s) benchmark::DoNotOptimize(clusterLights(p->lights, p->clustering));
    });
    registerStage("regions", i, [p](benchmark::State& s) {
      for (auto _ : s) benchmark::DoNotOptimize(visibleLightLists(p->regions, p->lights));
    });
    // The renderer's shadow groups (client/render/shadow_groups.h): S = 64 maps shared by the N
    // lights, seeded by the first 64 (the equal-power lights' most important).
    for (const auto grouping :
         {render::ShadowGrouping::Cluster, render::ShadowGrouping::NearestCaster}) {
      registerStage(
          grouping == render::ShadowGrouping::Cluster ? "shadow_groups" : "shadow_nearest", i,
          [p, grouping](benchmark::State& s) {
            std::vector<std::uint32_t> seeds(std::min<std::size_t>(64, p->lights.lights.size()));
            std::iota(seeds.begin(), seeds.end(), 0U);
            for (auto _ : s)
              benchmark::DoNotOptimize(render::groupShadows(p->lights.lights, seeds, grouping));
          });
    }
    // The capture chain, what vemd does per frame: tables, lights, FIR, clustering; and the same
    // plus the angular regions, which the renderer builds from each light set.
    const auto cells = std::make_shared<const LightCells>(
        lightCellsFor(MapLayout::Hemisphere, pattern, SamplerKind::Havran));
    for (const bool withRegions : {false, true}) {
      registerStage(withRegions ? "chain_regions" : "chain", i,
                    [p, pattern, cells, withRegions](benchmark::State& s) {
                      TemporalFilter filter(presetTaps(FilterPreset::Paper9));
                      std::uint64_t seq = 0;
                      for (auto _ : s) {
                        p->tables = buildSamplingTables(p->map, std::move(p->tables));
                        const LightSet raw =
                            generateLights(p->tables, pattern, SamplerKind::Havran, *cells);
                        const FilterResult filtered = filter.push(seq++, raw);
                        benchmark::DoNotOptimize(clusterLights(*filtered.lights, p->clustering));
                        if (withRegions)
                          benchmark::DoNotOptimize(visibleLightLists(p->regions, *filtered.lights));
                      }
                    });
    }
  }
}

}  // namespace vem::bench
