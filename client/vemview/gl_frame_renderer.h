// The OpenGL renderer behind vemview's FrameRenderer (frame_renderer.h): a GLFW window, or
// headless through EGL (--headless); each frame rendered, read back as linear radiance (for the
// tone statistics and the EXR files) and, in a window, tone-mapped onto the screen.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/vemview/frame_renderer.h"

namespace vem::view {

[[nodiscard]] std::expected<std::unique_ptr<FrameRenderer>, std::string> makeGlFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry);

}  // namespace vem::view
