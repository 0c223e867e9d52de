// The two renderers of the study behind one interface: render one configuration of the study
// scene under one map, timed. Times are wall-clock milliseconds per frame, the median over
// `frames` frames after one untimed warm-up frame (OpenGL) or with none (Embree: a frame costs
// seconds and has no caches to warm).
//
// - Embree (renderWithLights, 2 threads): the whole frame, ray-traced shadows for every light.
// - OpenGL: every timed frame redraws its shadow maps (the study measures a frame whose lights
//   changed, not a reused atlas); the time runs from the render call to the finished image.
#pragma once

#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "bench/render/study_setup.h"
#include "bench/render/study_sweeps.h"
#include "client/embree/embree_scene.h"
#include "client/render/environment_lighting.h"
#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"

namespace vem::bench {

struct TimedFrame {
  double medianMs = 0.0;
  std::vector<double> framesMs;
  double shadowMedianMs = 0.0;  // OpenGL: the shadow pass's share of the frame (0 for Embree)
  std::vector<double> shadowFramesMs;
  render::LinearImage image;  // the last timed frame
};

class StudyRenderer {
 public:
  virtual ~StudyRenderer() = default;
  // The error when the renderer cannot draw the configuration (e.g. no memory for the maps).
  // environment: shading by ratio from it (built from map.cube for the scene's materials), or
  // nullptr: by the lights.
  [[nodiscard]] virtual std::expected<TimedFrame, std::string> render(
      const StudyConfig& config, const StudyMap& map, const render::ShadingLights& lights,
      const render::EnvironmentLighting* environment) = 0;
};

[[nodiscard]] double medianOf(std::vector<double> values);

struct StudyImageSize {
  int widthPx = 320;
  int heightPx = 240;
};

// `embreeScene` and `geometry` are borrowed and must outlive the renderer. softShadows: by ratio,
// embree::LightRenderOptions::softShadows.
[[nodiscard]] std::unique_ptr<StudyRenderer> makeEmbreeStudyRenderer(
    const embree::EmbreeScene& embreeScene, const StudyScene& scene,
    const render::LightingGeometry& geometry, StudyImageSize size, int frames,
    bool softShadows = false);

struct GlStudyRenderer {
  std::unique_ptr<StudyRenderer> renderer;
  std::string timingLabel;   // GlContext::timingLabel()
  std::string rendererName;  // GL_RENDERER
  std::string version;       // GL_VERSION
  bool software = true;
};

// A headless context and the OpenGL renderer of the scene; the error when there is no GL 3.3.
// `scene` and `geometry` (the tables the frames' lights are built on) are borrowed and must
// outlive the renderer.
[[nodiscard]] std::expected<GlStudyRenderer, std::string> makeGlStudyRenderer(
    const StudyScene& scene, const render::LightingGeometry& geometry, StudyImageSize size,
    int frames);

}  // namespace vem::bench
