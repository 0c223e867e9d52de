#include "client/embree/surface_classes.h"

#include "client/embree/parallel_rows.h"
#include "util/contract.h"

namespace vem::embree {

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
          objectMeshes[hit->meshIndex] ? render::SurfaceClass::Object : render::SurfaceClass::Local;
    }
  });
  return classes;
}

}  // namespace vem::embree
