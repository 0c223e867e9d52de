#include "bench/render/study_sweeps.h"

#include <algorithm>

#include <fmt/format.h>

namespace vem::bench {
namespace {

constexpr std::size_t kBaseLights = 256;
constexpr std::size_t kBaseShadowed = 64;
constexpr int kBaseShadowMapPx = 256;

StudyConfig baseConfig(RendererKind renderer, std::size_t lights) {
  StudyConfig config;
  config.renderer = renderer;
  config.lighting.lightCount = lights;
  config.lighting.shadowedCount = std::min(lights, kBaseShadowed);
  config.lighting.regions = true;
  config.lighting.clusterBudget = 0;
  config.shadowMapPx = kBaseShadowMapPx;
  return config;
}

std::vector<RendererKind> renderers(bool withGl) {
  if (withGl) return {RendererKind::Gl, RendererKind::Embree};
  return {RendererKind::Embree};
}

Sweep lightCountSweep(bool withGl) {
  Sweep sweep{"a", "Light count N (S = min(N, 64) shadow maps of 256 px, regions on)", "N", {}};
  for (const RendererKind renderer : renderers(withGl)) {
    SweepSeries series{rendererLabel(renderer), {}};
    for (std::size_t n = 4; n <= 1024; n *= 2) {
      series.points.push_back({baseConfig(renderer, n), fmt::format("{}", n)});
    }
    sweep.series.push_back(std::move(series));
  }
  return sweep;
}

Sweep shadowCountSweep() {
  Sweep sweep{"b", "Shadowed lights S (N = 256, 256 px maps, regions on)", "S", {}};
  SweepSeries series{"OpenGL", {}};
  for (const std::size_t s : {0U, 4U, 16U, 64U, 256U}) {
    StudyConfig config = baseConfig(RendererKind::Gl, kBaseLights);
    config.lighting.shadowedCount = s;
    series.points.push_back({config, fmt::format("{}", s)});
  }
  sweep.series.push_back(std::move(series));
  return sweep;
}

Sweep resolutionSweep() {
  Sweep sweep{"c", "Shadow-map resolution (N = 256, S = 64, regions on)", "px", {}};
  SweepSeries series{"OpenGL", {}};
  for (const int px : {64, 128, 256, 512, 1024}) {
    StudyConfig config = baseConfig(RendererKind::Gl, kBaseLights);
    config.shadowMapPx = px;
    series.points.push_back({config, fmt::format("{}", px)});
  }
  sweep.series.push_back(std::move(series));
  return sweep;
}

Sweep regionSweep(bool withGl) {
  Sweep sweep{"d", "Angular regions on and off (S = min(N, 64), 256 px maps)", "N", {}};
  for (const RendererKind renderer : renderers(withGl)) {
    for (const bool regions : {true, false}) {
      SweepSeries series{
          fmt::format("{}, regions {}", rendererLabel(renderer), regions ? "on" : "off"), {}};
      for (std::size_t n = 16; n <= 1024; n *= 2) {
        StudyConfig config = baseConfig(renderer, n);
        config.lighting.regions = regions;
        series.points.push_back({config, fmt::format("{}", n)});
      }
      sweep.series.push_back(std::move(series));
    }
  }
  return sweep;
}

Sweep clusteringSweep(bool withGl) {
  Sweep sweep{"e", "Clustering budget Q (S = 64 shadow maps of 256 px, regions on)", "Q", {}};
  for (const RendererKind renderer : renderers(withGl)) {
    for (const std::size_t n : {256U, 1024U}) {
      SweepSeries series{fmt::format("{}, N = {}", rendererLabel(renderer), n), {}};
      for (const int q : {8, 32, 72, 128, 0}) {  // 72: vemd's default budget
        StudyConfig config = baseConfig(renderer, n);
        config.lighting.clusterBudget = q;
        series.points.push_back({config, q == 0 ? std::string("off") : fmt::format("{}", q)});
      }
      sweep.series.push_back(std::move(series));
    }
  }
  return sweep;
}

// Issue 20 part 2: with S < N, lights share maps by group (each map at its group's mean) or read
// the nearest caster's (the paper's scheme). The error should keep falling with N at fixed S.
Sweep shadowGroupSweep() {
  Sweep sweep{
      "f", "Shadow maps shared by S < N lights (S = 64 maps of 256 px, regions on)", "N", {}};
  for (const render::ShadowGrouping grouping :
       {render::ShadowGrouping::Cluster, render::ShadowGrouping::NearestCaster}) {
    SweepSeries series{grouping == render::ShadowGrouping::Cluster
                           ? "OpenGL, a map per group of lights"
                           : "OpenGL, the nearest caster's map",
                       {}};
    for (std::size_t n = 64; n <= 1024; n *= 2) {
      StudyConfig config = baseConfig(RendererKind::Gl, n);
      config.lighting.shadowGrouping = grouping;
      series.points.push_back({config, fmt::format("{}", n)});
    }
    sweep.series.push_back(std::move(series));
  }
  return sweep;
}

}  // namespace

const char* rendererLabel(RendererKind kind) {
  return kind == RendererKind::Gl ? "OpenGL" : "Embree";
}

std::string StudyConfig::key() const {
  // Embree traces every light's shadow: S and the map resolution do not change its frame.
  const bool gl = renderer == RendererKind::Gl;
  const bool nearest = gl && lighting.shadowGrouping == render::ShadowGrouping::NearestCaster;
  return fmt::format("{} N{} S{} px{} r{} q{}{}", rendererLabel(renderer), lighting.lightCount,
                     gl ? lighting.shadowedCount : 0, gl ? shadowMapPx : 0,
                     lighting.regions ? 1 : 0, lighting.clusterBudget, nearest ? " nearest" : "");
}

std::vector<Sweep> studySweeps(bool withGl) {
  std::vector<Sweep> sweeps{lightCountSweep(withGl)};
  if (withGl) {
    sweeps.push_back(shadowCountSweep());
    sweeps.push_back(resolutionSweep());
  }
  sweeps.push_back(regionSweep(withGl));
  sweeps.push_back(clusteringSweep(withGl));
  if (withGl) sweeps.push_back(shadowGroupSweep());
  return sweeps;
}

}  // namespace vem::bench
