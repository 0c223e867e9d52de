// The OpenGL half of study_renderer.h: client/gl's GlRenderer in a headless context. The renderer
// is recreated when a configuration needs another shadow-map resolution or more atlas slots.
// Shadow maps are reused by GlRenderer when a frame's lightsKey equals the previous frame's, so
// the timed frames alternate between the frame's lights and a copy with another key (the same
// lights and casters): every timed frame redraws its maps, which the frame stats confirm.
#include <algorithm>
#include <chrono>
#include <functional>

#include <fmt/format.h>

#include "bench/render/study_renderer.h"
#include "client/gl/gl_context.h"
#include "client/gl/gl_renderer.h"

namespace vem::bench {
namespace {

// Atlases up to this side unless a configuration needs more slots (1024 px maps, S = 64).
constexpr int kAtlasBudgetPx = 4096;

std::size_t atlasSlotsFor(int shadowMapPx, std::size_t shadowed) {
  const auto perSide = std::size_t(std::max(kAtlasBudgetPx / shadowMapPx, 1));
  return std::clamp(perSide * perSide, std::max<std::size_t>(shadowed, 1), render::kMaxShadowMaps);
}

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

class GlStudyRendererImpl final : public StudyRenderer {
 public:
  GlStudyRendererImpl(std::unique_ptr<gl::GlContext> context, const StudyScene& scene,
                      const render::LightingGeometry& geometry, StudyImageSize size, int frames)
      : context_(std::move(context)),
        scene_(scene),
        geometry_(geometry),
        size_(size),
        frames_(std::max(frames, 1)) {}

  std::expected<TimedFrame, std::string> render(
      const StudyConfig& config, const StudyMap& map, const render::ShadingLights& lights,
      const render::EnvironmentLighting* environment) override {
    if (auto ready = prepare(config); !ready) return std::unexpected(ready.error());
    render::ShadingLights rekeyed = lights;
    rekeyed.lightsKey = ~lights.lightsKey;
    // A new version for every prefiltered environment (its peak factor follows N), so the
    // renderer uploads it.
    const std::uint64_t cubeVersion = std::hash<std::string>{}(
        map.name + (environment != nullptr ? fmt::format("/{}", environment->peakLuminance) : ""));
    // The environment is built once per map (its upload is not part of the timed frames).
    const gl::RatioShading ratio{environment, cubeVersion};
    (void)renderer_->render(scene_.camera, rekeyed, &map.cube, cubeVersion, ratio);  // warm-up
    TimedFrame out;
    for (int frame = 0; frame < frames_; ++frame) {
      const render::ShadingLights& now = frame % 2 == 0 ? lights : rekeyed;
      const auto start = std::chrono::steady_clock::now();
      const gl::GlFrameStats stats =
          renderer_->render(scene_.camera, now, &map.cube, cubeVersion, ratio);
      out.framesMs.push_back(msSince(start));
      out.shadowFramesMs.push_back(stats.shadowPassMs);
      if (stats.shadowMapsReused != 0 || stats.shadowMapsRendered != lights.shadowDirs.size()) {
        return std::unexpected(fmt::format(
            "{} of {} shadow maps drawn, {} reused: not a frame "
            "with new lights",
            stats.shadowMapsRendered, lights.shadowDirs.size(), stats.shadowMapsReused));
      }
    }
    out.medianMs = medianOf(out.framesMs);
    out.shadowMedianMs = medianOf(out.shadowFramesMs);
    out.image = renderer_->readLinear();
    return out;
  }

 private:
  // The renderer for the configuration's map resolution and shadow count.
  std::expected<void, std::string> prepare(const StudyConfig& config) {
    const std::size_t shadowed = config.lighting.shadowedCount;
    if (renderer_ && shadowMapPx_ == config.shadowMapPx &&
        renderer_->shadowMapCapacity() >= shadowed) {
      return {};
    }
    renderer_.reset();
    gl::GlRendererOptions options;
    options.widthPx = size_.widthPx;
    options.heightPx = size_.heightPx;
    options.shadowMapPx = config.shadowMapPx;
    options.maxShadowMaps = atlasSlotsFor(config.shadowMapPx, shadowed);
    options.geometry = &geometry_;
    auto made = gl::GlRenderer::create(scene_.scene, options);
    if (!made) return std::unexpected(made.error());
    renderer_ = std::move(*made);
    shadowMapPx_ = config.shadowMapPx;
    if (renderer_->shadowMapCapacity() < shadowed) {
      return std::unexpected(fmt::format("the atlas holds {} maps of {} px, {} wanted",
                                         renderer_->shadowMapCapacity(), shadowMapPx_, shadowed));
    }
    return {};
  }

  std::unique_ptr<gl::GlContext> context_;  // declared first: outlives the renderer
  std::unique_ptr<gl::GlRenderer> renderer_;
  int shadowMapPx_ = 0;
  const StudyScene& scene_;
  const render::LightingGeometry& geometry_;
  StudyImageSize size_;
  int frames_;
};

}  // namespace

std::expected<GlStudyRenderer, std::string> makeGlStudyRenderer(
    const StudyScene& scene, const render::LightingGeometry& geometry, StudyImageSize size,
    int frames) {
  auto context = gl::GlContext::headless(size.widthPx, size.heightPx);
  if (!context) return std::unexpected(context.error());
  GlStudyRenderer out;
  out.timingLabel = (*context)->timingLabel();
  out.rendererName = (*context)->rendererName();
  out.version = (*context)->versionString();
  out.software = (*context)->softwareRenderer();
  out.renderer =
      std::make_unique<GlStudyRendererImpl>(std::move(*context), scene, geometry, size, frames);
  return out;
}

}  // namespace vem::bench
