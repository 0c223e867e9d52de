#include "bench/render/study_run.h"

#include <cstdlib>

#include <fmt/format.h>

#include "client/render/image_metrics.h"

namespace vem::bench {
namespace {

std::expected<PointResult, std::string> measure(const StudyConfig& config, const StudyMap& map,
                                                const StudyScene& scene,
                                                const render::LightingGeometry& geometry,
                                                const StudyReference& reference,
                                                StudyRenderer& renderer) {
  const render::ShadingLights lights = studyLights(map, scene, geometry, config.lighting);
  const auto frame = renderer.render(config, map, lights, nullptr);
  if (!frame)
    return std::unexpected(fmt::format("{} on {}: {}", config.key(), map.name, frame.error()));
  const render::ImageError error = render::compareImages(frame->image, reference.image);
  return PointResult{frame->medianMs,        frame->shadowMedianMs,
                     error.relativeRms,      error.meanAbsoluteRelative,
                     error.coverageMismatch, lights.diffuse.lights.size()};
}

ReferenceFacts factsOf(const StudyReference& reference) {
  return {reference.samplesPerPixel, reference.relativeError, reference.converged,
          reference.renderSeconds, reference.fromCache};
}

}  // namespace

const PointResult& MapStudy::at(const StudyConfig& config) const {
  const auto it = results.find(config.key());
  if (it == results.end()) {
    fmt::print(stderr, "MapStudy::at: {} was not measured on {}\n", config.key(), map);
    std::abort();
  }
  return it->second;
}

std::expected<MapStudy, std::string> runMapStudy(const StudyMap& map, const StudyScene& scene,
                                                 const render::LightingGeometry& geometry,
                                                 const StudyReference& reference,
                                                 const std::vector<Sweep>& sweeps,
                                                 StudyRenderers renderers) {
  MapStudy out{map.name,
               map.damage.has_value(),
               map.character.peakToMean,
               map.character.topShareOfPower,
               factsOf(reference),
               {}};
  for (const Sweep& sweep : sweeps) {
    for (const SweepSeries& series : sweep.series) {
      for (const SweepPoint& point : series.points) {
        const std::string key = point.config.key();
        if (out.results.contains(key)) continue;
        StudyRenderer* renderer =
            point.config.renderer == RendererKind::Gl ? renderers.gl : renderers.embree;
        if (renderer == nullptr) continue;
        const auto result = measure(point.config, map, scene, geometry, reference, *renderer);
        if (!result) return std::unexpected(result.error());
        fmt::print(stderr, "  {} {}: {:.1f} ms, relative RMS {:.4f}, mean abs {:.4f}\n", map.name,
                   key, result->timeMs, result->relativeRms, result->meanAbsoluteRelative);
        out.results.emplace(key, *result);
      }
    }
  }
  return out;
}

}  // namespace vem::bench
