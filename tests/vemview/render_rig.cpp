#include "vemview/render_rig.h"

#include <cstdlib>
#include <iostream>

#include "client/embree/light_renderer.h"
#include "client/scene/default_scene.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "mapio/map_file.h"

namespace vem::testing {
namespace {

template <class T>
T orDie(std::expected<T, std::string> value, const char* what) {
  if (!value) {
    std::cerr << what << ": " << value.error() << "\n";
    std::abort();
  }
  return std::move(*value);
}

}  // namespace

RigOptions sphereOnAPlaneUnderTheSun() {
  RigOptions options;
  options.sceneName = "spheres";
  options.mapName = "sky";
  options.widthPx = 320;
  options.heightPx = 240;
  options.shadowMapPx = 256;
  return options;
}

RenderRig::RenderRig(const RigOptions& options)
    : options_(options), geometry_(render::makeLightingGeometry()) {
  scene_ = scene::builtinScene(options.sceneName).value();
  camera_ = scene::viewingCamera(scene_);
  auto map = mapio::loadMap(std::string(VEM_SHARED_DATA_DIR) + "/hdri/" + options.mapName + ".exr");
  if (!map) {
    std::cerr << map.error().message << "\n";
    std::abort();
  }
  map_ = std::move(*map);
  const SamplingTables tables = buildSamplingTables(map_);
  allLights_ = generateLights(tables, defaultSamplingPattern(map_.layout).first(options.maxLights),
                              SamplerKind::Havran);
  cube_ = cubeMapFromEnvMap(map_, 128, 8);
  embree_ = std::make_unique<embree::EmbreeScene>(
      orDie(embree::EmbreeScene::build(scene_), "Embree scene"));
  context_ = orDie(gl::GlContext::headless(options.widthPx, options.heightPx), "EGL context");
  gl::GlRendererOptions glOptions;
  glOptions.widthPx = options.widthPx;
  glOptions.heightPx = options.heightPx;
  glOptions.shadowMapPx = options.shadowMapPx;
  glOptions.geometry = &geometry_;
  glRenderer_ = orDie(gl::GlRenderer::create(scene_, glOptions), "GL renderer");
}

render::ShadingLights RenderRig::lights(std::size_t count, std::size_t shadowed, bool regions,
                                        int clusterBudget) const {
  render::LightingOptions o;
  o.lightCount = count;
  o.shadowedCount = shadowed;
  o.regions = regions;
  o.glossyPass = scene::anyGlossy(scene_);
  o.clusterBudget = clusterBudget;
  o.clusterLayout = map_.layout;
  return render::buildShadingLights(allLights_, geometry_, o);
}

render::LinearImage RenderRig::gl(const render::ShadingLights& lights) {
  (void)glRenderer_->render(camera_, lights, &cube_, 1);
  return glRenderer_->readLinear();
}

render::LinearImage RenderRig::embree(const render::ShadingLights& lights) const {
  return embree::renderWithLights(*embree_, camera_, options_.widthPx, options_.heightPx, lights,
                                  geometry_, &cube_);
}

embree::ReferenceResult RenderRig::reference(double targetError, int maxSamples) const {
  embree::ReferenceOptions o;
  o.targetRelativeError = targetError;
  o.maxSamples = maxSamples;
  return embree::renderReference(*embree_, camera_, options_.widthPx, options_.heightPx, map_, o);
}

}  // namespace vem::testing
