// Running the study on one map: every point of every sweep rendered by its renderer and compared
// with the reference (render/image_metrics.h: relative RMS and mean absolute relative luminance
// error over covered pixels). Configurations shared by several sweeps are measured once.
#pragma once

#include <expected>
#include <map>
#include <string>
#include <vector>

#include "bench/render/reference_cache.h"
#include "bench/render/study_renderer.h"
#include "bench/render/study_setup.h"
#include "bench/render/study_sweeps.h"

namespace vem::bench {

struct PointResult {
  double timeMs = 0.0;        // median frame time
  double shadowPassMs = 0.0;  // OpenGL: median shadow pass (0 for Embree)
  double relativeRms = 0.0;
  double meanAbsoluteRelative = 0.0;
  std::size_t coverageMismatch = 0;
  std::size_t drawnLights = 0;  // diffuse lights after clustering
};

struct ReferenceFacts {
  int samplesPerPixel = 0;
  double relativeError = 0.0;
  bool converged = false;
  double renderSeconds = 0.0;
  bool fromCache = false;
};

struct MapStudy {
  std::string map;
  bool damaged = false;  // StudyMap::damage: shown as a hard case, out of the means over the maps
  double peakToMean = 0.0;
  double topShareOfPower = 0.0;
  ReferenceFacts reference;
  std::map<std::string, PointResult> results;  // by StudyConfig::key()

  // The result of `config`; a contract: aborts when it was not measured.
  [[nodiscard]] const PointResult& at(const StudyConfig& config) const;
};

struct StudyRenderers {
  StudyRenderer* gl = nullptr;  // null: the OpenGL points are not in the sweeps
  StudyRenderer* embree = nullptr;
};

// The first renderer's error stops the study.
[[nodiscard]] std::expected<MapStudy, std::string> runMapStudy(
    const StudyMap& map, const StudyScene& scene, const render::LightingGeometry& geometry,
    const StudyReference& reference, const std::vector<Sweep>& sweeps, StudyRenderers renderers);

}  // namespace vem::bench
