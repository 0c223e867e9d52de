#include "client/embree/differential_renderer.h"

#include <chrono>
#include <utility>

#include "client/embree/parallel_rows.h"
#include "util/contract.h"

namespace vem::embree {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::expected<DifferentialRenderer, std::string> DifferentialRenderer::build(
    const scene::LocalComposition& composition) {
  VEM_EXPECTS(composition.objectMeshes.size() == composition.withObjects.meshes.size());
  auto withObjects = EmbreeScene::build(composition.withObjects);
  if (!withObjects) {
    return std::unexpected(withObjects.error());
  }
  auto localOnly = EmbreeScene::build(composition.localOnly);
  if (!localOnly) {
    return std::unexpected(localOnly.error());
  }
  return DifferentialRenderer(std::move(*withObjects), std::move(*localOnly),
                              composition.objectMeshes);
}

DifferentialRenderer::DifferentialRenderer(EmbreeScene withObjects, EmbreeScene localOnly,
                                           std::vector<bool> objectMeshes)
    : withObjects_(std::move(withObjects)),
      localOnly_(std::move(localOnly)),
      objectMeshes_(std::move(objectMeshes)) {}

render::DifferentialLayers DifferentialRenderer::render(
    const scene::ViewCamera& camera, int widthPx, int heightPx,
    const render::ShadingLights& lights, const render::LightingGeometry& geometry,
    const CubeMap* cube, const LightRenderOptions& options, std::uint64_t withoutKey,
    DifferentialTiming* timing, bool differential) {
  DifferentialTiming t;
  render::DifferentialLayers layers;
  auto start = std::chrono::steady_clock::now();
  layers.withObjects =
      renderWithLights(withObjects_, camera, widthPx, heightPx, lights, geometry, cube, options);
  t.withObjectsMs = msSince(start);
  t.reusedWithout = withoutKey_ == withoutKey && without_.widthPx == widthPx &&
                    without_.heightPx == heightPx;
  if (!differential) {
    t.reusedWithout = false;
  } else if (!t.reusedWithout) {
    start = std::chrono::steady_clock::now();
    without_ =
        renderWithLights(localOnly_, camera, widthPx, heightPx, lights, geometry, cube, options);
    withoutKey_ = withoutKey;
    t.withoutObjectsMs = msSince(start);
  }
  if (differential) layers.withoutObjects = without_;
  start = std::chrono::steady_clock::now();
  layers.classes =
      surfaceClasses(withObjects_, objectMeshes_, camera, widthPx, heightPx, options.threadCount);
  t.classesMs = msSince(start);
  if (timing != nullptr) {
    *timing = t;
  }
  return layers;
}

std::vector<render::SurfaceClass> surfaceClasses(const EmbreeScene& scene,
                                                 const std::vector<bool>& objectMeshes,
                                                 const scene::ViewCamera& camera, int widthPx,
                                                 int heightPx, int threadCount) {
  VEM_EXPECTS(widthPx >= 1 && heightPx >= 1);
  std::vector<render::SurfaceClass> classes(std::size_t(widthPx) * std::size_t(heightPx),
                                            render::SurfaceClass::Background);
  forEachRow(heightPx, threadCount, [&](int row) {
    for (int x = 0; x < widthPx; ++x) {
      const scene::Ray ray =
          camera.primaryRay(float(x) + 0.5F, float(row) + 0.5F, widthPx, heightPx);
      const auto hit = scene.intersect(ray);
      if (!hit) {
        continue;
      }
      VEM_EXPECTS(hit->meshIndex < objectMeshes.size());
      classes[std::size_t(row) * std::size_t(widthPx) + std::size_t(x)] =
          objectMeshes[hit->meshIndex] ? render::SurfaceClass::Object
                                       : render::SurfaceClass::Local;
    }
  });
  return classes;
}

}  // namespace vem::embree
