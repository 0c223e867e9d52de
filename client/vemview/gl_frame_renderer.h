// The OpenGL renderer behind vemview's FrameRenderer (frame_renderer.h): a GLFW window, or
// headless through EGL (--headless); each frame rendered, read back as linear radiance (for the
// tone statistics and the EXR files) and, in a window, tone-mapped onto the screen.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/gl/gl_context.h"
#include "client/vemview/frame_renderer.h"

namespace vem::view {

// `context`: a GL context to render in, shared with other renderers (the composite's two layers);
// null: its own, a window or headless as the options say.
[[nodiscard]] std::expected<std::unique_ptr<FrameRenderer>, std::string> makeGlFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry, std::shared_ptr<gl::GlContext> context = nullptr);

}  // namespace vem::view
