#include "client/vemview/embree_frame_renderer.h"

#include <chrono>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "client/embree/embree_scene.h"
#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "client/vemview/prefiltered_environment.h"

namespace vem::view {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

class EmbreeFrameRenderer final : public FrameRenderer {
 public:
  EmbreeFrameRenderer(const ViewerOptions& options, const RenderPlan& plan,
                      embree::EmbreeScene scene, const render::LightingGeometry& geometry)
      : options_(options), environment_(plan), scene_(std::move(scene)), geometry_(geometry) {
    lightOptions_.cubeCoverage = plan.cubeMapCoverage;
    lightOptions_.softShadows = plan.softShadows;
  }

  std::string name() const override {
    return options_.renderer == RendererKind::Reference
               ? "Embree reference (Monte Carlo over the whole map, CPU)"
               : "Embree (the same lights, ray-traced shadows, CPU)";
  }

  RenderedFrame render(const scene::ViewCamera& camera, const render::ShadingLights& lights,
                       const InputFrame& input) override {
    const auto start = std::chrono::steady_clock::now();
    RenderedFrame frame;
    if (options_.renderer == RendererKind::Reference) {
      embree::ReferenceOptions reference;
      reference.targetRelativeError = options_.referenceError;
      reference.maxSamples = int(options_.referenceMaxSamples);
      embree::ReferenceResult result = embree::renderReference(
          scene_, camera, options_.widthPx, options_.heightPx, *input.map, reference);
      frame.image = std::move(result.image);
      frame.timing["samples_per_pixel"] = result.samplesPerPixel;
      frame.timing["relative_error"] = result.relativeError;
      frame.timing["converged"] = result.converged;
    } else {
      const PrefilteredEnvironment::Current environment =
          environment_.forCube(input.cube, scene_.materials());
      if (environment.builtMs) frame.timing["prefilter_ms"] = *environment.builtMs;
      lightOptions_.environment = environment.lighting;
      frame.image = embree::renderWithLights(scene_, camera, options_.widthPx, options_.heightPx,
                                             lights, geometry_, input.cube.get(), lightOptions_);
    }
    frame.renderMs = msSince(start);
    return frame;
  }

 private:
  const ViewerOptions& options_;
  PrefilteredEnvironment environment_;
  embree::EmbreeScene scene_;
  const render::LightingGeometry& geometry_;
  embree::LightRenderOptions lightOptions_;
};

}  // namespace

std::expected<std::unique_ptr<FrameRenderer>, std::string> makeEmbreeFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry) {
  auto built = embree::EmbreeScene::build(scene);
  if (!built) {
    return std::unexpected(built.error());
  }
  return std::make_unique<EmbreeFrameRenderer>(options, plan, std::move(*built), geometry);
}

}  // namespace vem::view
