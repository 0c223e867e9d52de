#include "client/vemview/gl_frame_renderer.h"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "client/gl/gl_context.h"
#include "client/gl/gl_renderer.h"
#include "client/render/image_files.h"
#include "client/render/shadow_draws.h"
#include "client/render/soft_shadows.h"
#include "client/vemview/prefiltered_environment.h"

namespace vem::view {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

class GlFrameRenderer final : public FrameRenderer {
 public:
  GlFrameRenderer(const ViewerOptions& options, const RenderPlan& plan,
                  const scene::Scene& scene, std::shared_ptr<gl::GlContext> context,
                  std::unique_ptr<gl::GlRenderer> renderer)
      : options_(options),
        softShadowMaps_(plan.softShadows ? plan.softShadowMaps : 0),
        materials_(scene.materials),
        environment_(plan),
        context_(std::move(context)),
        renderer_(std::move(renderer)) {}

  ~GlFrameRenderer() override {
    if (!options_.screenshot.empty() && context_->isWindow()) {
      saveScreenshot();
    }
  }
  GlFrameRenderer(const GlFrameRenderer&) = delete;
  GlFrameRenderer& operator=(const GlFrameRenderer&) = delete;

  std::string name() const override {
    return fmt::format("OpenGL {} on {}{}", context_->versionString(), context_->timingLabel(),
                       context_->isWindow() ? ", window" : ", headless (EGL)");
  }

  RenderedFrame render(const scene::ViewCamera& camera, const render::ShadingLights& lights,
                       const InputFrame& input) override {
    const auto start = std::chrono::steady_clock::now();
    context_->makeCurrent();  // the context may be shared (the composite's two layers)
    RenderedFrame frame;
    const PrefilteredEnvironment::Current environment = environment_.forCube(input.cube, materials_);
    if (environment.builtMs) frame.timing["prefilter_ms"] = *environment.builtMs;
    const render::ShadingLights& shading = withSoftShadows(lights, input, frame);
    const gl::GlFrameStats stats =
        renderer_->render(camera, shading, input.cube.get(), input.cubeVersion,
                          gl::RatioShading{environment.lighting, environment.version});
    const auto readStart = std::chrono::steady_clock::now();
    frame.image = renderer_->readLinear();
    frame.renderMs = msSince(start);
    frame.timing["shadow_pass_ms"] = stats.shadowPassMs;
    frame.timing["lighting_pass_ms"] = stats.lightingPassMs;
    frame.timing["gl_total_ms"] = stats.totalMs;
    frame.timing["readback_ms"] = msSince(readStart);
    frame.timing["shadow_maps_rendered"] = stats.shadowMapsRendered;
    frame.timing["shadow_maps_reused"] = stats.shadowMapsReused;
    frame.timing["cube_map_uploaded"] = stats.backgroundUploaded;
    return frame;
  }

  // The tone-mapped frame, then the overlay, into the window's back buffer, then the swap. The
  // --screenshot is read from the back buffer between the two: what the window shows without the
  // overlay, so it can be compared with the headless images.
  void present(const render::ToneParams& tone, const std::string& overlay) override {
    if (!context_->isWindow()) {
      return;
    }
    renderer_->presentToneMapped(tone);
    if (!options_.screenshot.empty()) {
      lastDisplay_ = renderer_->readDisplaySrgb8();  // the back buffer, before overlay and swap
    }
    renderer_->drawOverlay(overlay);
    setTitle(overlay.substr(0, overlay.find('\n')));
    context_->swapBuffers();
    context_->pollEvents();
  }

  bool open() override { return !context_->shouldClose(); }

  std::optional<std::size_t> shadowMapCapacity() const override {
    return renderer_->shadowMapCapacity();
  }

  // A drag across the whole window turns the camera half way round; dragging to the right turns
  // the scene to the right (the camera to its left, azimuth up).
  float takeOrbitDragRad() override {
    const glm::dvec2 dragPx = context_->takeLeftDragPx();
    return float(dragPx.x / double(renderer_->widthPx()) * std::numbers::pi);
  }

 private:
  // With soft shadows, the frame's lights with the maps beyond N spent on the strata
  // (render/shadow_draws.h), rebuilt only when the lights, their count or the cube map change
  // (so unchanged lights keep their maps); otherwise `lights` itself.
  const render::ShadingLights& withSoftShadows(const render::ShadingLights& lights,
                                               const InputFrame& input, RenderedFrame& frame) {
    if (softShadowMaps_ == 0 || !input.cube) return lights;
    const SoftKey key{input.seq, input.cubeVersion, lights.diffuse.lights.size()};
    if (!soft_ || softKey_ != key) {
      const auto start = std::chrono::steady_clock::now();
      soft_ = lights;
      const render::ShadowStrata strata =
          render::buildShadowStrata(lights.diffuse.lights, *input.cube);
      const std::size_t budget = std::min(softShadowMaps_, renderer_->shadowMapCapacity());
      (void)render::spendShadowMapsOnStrata(*soft_, strata, budget);
      softKey_ = key;
      frame.timing["soft_shadow_strata_ms"] = msSince(start);
    }
    std::size_t strata = 0;
    for (const std::uint32_t draws : soft_->shadowDrawsOfDiffuse) strata += draws;
    frame.strataShadowMaps = strata;
    frame.timing["strata_shadow_maps"] = strata;
    return *soft_;
  }

  struct SoftKey {
    std::uint64_t seq = 0;
    std::uint64_t cubeVersion = 0;
    std::size_t lightCount = 0;
    bool operator==(const SoftKey&) const = default;
  };

  void saveScreenshot() {
    if (lastDisplay_.empty()) {
      return;
    }
    if (auto saved = render::saveSrgbPng(lastDisplay_, renderer_->widthPx(), renderer_->heightPx(),
                                         options_.screenshot);
        !saved) {
      fmt::print(stderr, "vemview: error: {}\n", saved.error());
    }
  }

  void setTitle(const std::string& title) {
    if (title != title_) {
      title_ = title;
      context_->setTitle("vemview: " + title_);
    }
  }

  const ViewerOptions& options_;
  std::size_t softShadowMaps_ = 0;  // the plan's, 0 without soft shadows
  std::optional<render::ShadingLights> soft_;
  SoftKey softKey_;
  std::vector<scene::Material> materials_;
  PrefilteredEnvironment environment_;
  std::shared_ptr<gl::GlContext> context_;
  std::unique_ptr<gl::GlRenderer> renderer_;
  std::vector<std::uint8_t> lastDisplay_;
  std::string title_;
};

}  // namespace

std::expected<std::unique_ptr<FrameRenderer>, std::string> makeGlFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry, std::shared_ptr<gl::GlContext> shared) {
  std::shared_ptr<gl::GlContext> context = std::move(shared);
  if (!context) {
    auto made = options.headless
                    ? gl::GlContext::headless(options.widthPx, options.heightPx)
                    : gl::GlContext::window(options.widthPx, options.heightPx, "vemview");
    if (!made) {
      return std::unexpected(made.error());
    }
    context = std::move(*made);
  }
  gl::GlRendererOptions glOptions;
  glOptions.widthPx = options.widthPx;
  glOptions.heightPx = options.heightPx;
  glOptions.shadowMapPx = plan.shadowMapPx;
  glOptions.maxShadowMaps =
      std::max<std::size_t>({plan.lighting.shadowedCount, plan.softShadowMaps, 1});
  glOptions.presentToWindow = !options.headless;
  glOptions.environmentCoverage = plan.cubeMapCoverage;
  glOptions.geometry = &geometry;
  if (plan.composite) glOptions.shadowCasterBounds = plan.composite->objectBounds;
  context->makeCurrent();
  auto renderer = gl::GlRenderer::create(scene, glOptions);
  if (!renderer) {
    return std::unexpected(renderer.error());
  }
  return std::make_unique<GlFrameRenderer>(options, plan, scene, std::move(context),
                                           std::move(*renderer));
}

}  // namespace vem::view
