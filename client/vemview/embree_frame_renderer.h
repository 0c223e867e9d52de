// The Embree renderers behind vemview's FrameRenderer (frame_renderer.h): `embree` (the frame's
// lights, ray-traced shadows) and `reference` (Monte Carlo over the input's whole map).
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/vemview/frame_renderer.h"

namespace vem::view {

[[nodiscard]] std::expected<std::unique_ptr<FrameRenderer>, std::string> makeEmbreeFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry);

}  // namespace vem::view
