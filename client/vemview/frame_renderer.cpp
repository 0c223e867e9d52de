#include "client/vemview/frame_renderer.h"

#include "client/vemview/embree_frame_renderer.h"
#include "client/vemview/gl_frame_renderer.h"

namespace vem::view {

std::expected<std::unique_ptr<FrameRenderer>, std::string> makeFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry) {
  if (options.renderer == RendererKind::Gl) {
    return makeGlFrameRenderer(options, plan, scene, geometry);
  }
  return makeEmbreeFrameRenderer(options, plan, scene, geometry);
}

}  // namespace vem::view
