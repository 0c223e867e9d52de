// FrameRenderer: one of vemview's three ways of drawing a frame, behind one interface so the loop
// does not care which (viewer_options.h --renderer):
// - gl: the OpenGL renderer (client/gl): shadow-map atlas, angular regions, glossy L/H, in a
//   window or headless (EGL);
// - embree: the same lights, ray-traced shadows (client/embree);
// - reference: Monte Carlo over the whole environment map until converged (client/embree), the
//   ground truth; needs the map (--map).
// Times in ms, measured on the CPU's steady clock around work that has finished (GL: glFinish).
#pragma once

#include <cstddef>
#include <expected>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"
#include "client/render/tone_mapping.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"
#include "client/vemview/light_input.h"
#include "client/vemview/render_plan.h"
#include "client/vemview/viewer_options.h"

namespace vem::view {

struct RenderedFrame {
  render::LinearImage image;
  double renderMs = 0.0;          // the renderer's whole frame, readback included
  nlohmann::ordered_json timing;  // its own figures (pass times, maps rendered/reused...)
  std::size_t strataShadowMaps = 0;  // OpenGL's soft shadows: maps along strata draws
  // The picture is display-referred (a composite into an 8-bit plate): encode it as sRGB with
  // no tone mapping, so what the camera saw comes out as it came in.
  bool displayReferred = false;
  // --plate: the lights' age at the picture and the plate's state (status_text.h's LightCounts).
  std::optional<double> lightAgeSec;
  std::string plateState;
};

class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  [[nodiscard]] virtual std::string name() const = 0;  // "OpenGL (llvmpipe, software)", ...
  [[nodiscard]] virtual RenderedFrame render(const scene::ViewCamera& camera,
                                             const render::ShadingLights& lights,
                                             const InputFrame& input) = 0;
  // A renderer with an input of its own (--plate's pictures) polls it before each frame: the
  // version changes when a new picture came (the frame is redrawn), and ownInputEnded() once a
  // file source (a video, a sequence) has no more. 0 and false for the others.
  [[nodiscard]] virtual std::uint64_t pollOwnInput() { return 0; }
  [[nodiscard]] virtual bool ownInputEnded() const { return false; }
  // When its input's current picture was captured, on the system clock (a live camera), so the
  // loop can pick the light frame captured nearest to it; nothing otherwise.
  [[nodiscard]] virtual std::optional<double> ownInputCaptureUnixSec() const {
    return std::nullopt;
  }
  // Shows the last frame tone-mapped, with `overlay` text lines (windows only).
  virtual void present(const render::ToneParams& /*tone*/, const std::string& /*overlay*/) {}
  // False once the user closed the window.
  [[nodiscard]] virtual bool open() { return true; }
  // Mouse-drag orbit since the last call, radians (windows only).
  [[nodiscard]] virtual float takeOrbitDragRad() { return 0.0F; }
  // How many shadow maps it can hold (the GL atlas is bounded by GL_MAX_TEXTURE_SIZE); nothing
  // when unbounded (ray-traced shadows).
  [[nodiscard]] virtual std::optional<std::size_t> shadowMapCapacity() const {
    return std::nullopt;
  }
};

[[nodiscard]] std::expected<std::unique_ptr<FrameRenderer>, std::string> makeFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry);

}  // namespace vem::view
