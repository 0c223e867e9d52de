// The mixed-reality frame renderer (--plate, issue 21): synthetic objects composited into the
// scene camera's picture by differential rendering (render/differential_composite.h). Its two
// layers, the local scene with the objects and without them, are frames of vemview's own
// renderers (OpenGL, in one shared context, or Embree; frame_renderer.h) drawn from the plate
// camera (plate_view.h) at the render size; each pixel's surface class comes from its primary ray
// (embree/surface_classes.h); the layers are resampled into the plate's pixels
// (render/layer_resampling.h).
//
// Per frame: the newest plate picture (pollOwnInput; a live source that stopped, or a video that
// ended, keeps its last picture and the frame says so), the render with the objects, the render
// without them only when the lights, the cube map or the plate camera changed (kept otherwise),
// the local surfaces' albedo updated from the plate, the composite at the plate's size in the
// plate's units. With no differential pass (render_plan.h's CompositePlan) there is no render
// without the objects: they are drawn over the plate. Its timing: plate_decode_ms,
// with_objects_ms, without_objects_ms, without_reused, classes_ms, resample_ms, composite_ms,
// plate_seq, plate_state, plate_capture_s, albedo_frames, albedo_clamped_px, object_px, local_px,
// plate_to_composite_ms (from the picture's decode to its composite), light_age_s.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/render/shading_lights.h"
#include "client/scene/local_scene.h"
#include "client/vemview/frame_renderer.h"
#include "client/vemview/plate_source.h"
#include "client/vemview/plate_view.h"

namespace vem::view {

// `composition` in the light probe's world (plate_view.h's turn applied); options.renderer picks
// the layers' renderer.
[[nodiscard]] std::expected<std::unique_ptr<FrameRenderer>, std::string>
makeCompositeFrameRenderer(const ViewerOptions& options, const RenderPlan& plan,
                           const scene::LocalComposition& composition,
                           const render::LightingGeometry& geometry,
                           std::unique_ptr<PlateSource> plate, PlateView view);

}  // namespace vem::view
