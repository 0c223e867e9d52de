// What vemview --plate needs before its first frame (composite_frame_renderer.h): the plate
// source, the plate camera (plate_view.h: a plate-camera file, or the simulated world's), the
// objects placed (--place) and, with the local scene (the floor plane, --local-scene's proxies or
// the simulated world's), turned into the light probe's world; the composite's plan.
// Every failure is one sentence naming the file or option.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include "client/scene/local_scene.h"
#include "client/vemview/light_input.h"
#include "client/vemview/plate_source.h"
#include "client/vemview/plate_view.h"
#include "client/vemview/render_plan.h"
#include "client/vemview/viewer_options.h"

namespace vem::view {

struct CompositeSetup {
  std::unique_ptr<PlateSource> plate;
  PlateView view;
  scene::LocalComposition composition;  // in the light probe's world
  CompositePlan plan;
};

// `objects`: the scene (--scene) in the plate's world; `firstInput`: the light input's first frame
// (its map films the simulated plate).
[[nodiscard]] std::expected<CompositeSetup, std::string> setUpComposite(
    const ViewerOptions& options, const scene::Scene& objects, const InputFrame& firstInput);

// The objects moved by --place: turned by yaw about +Y, then moved to (x, y, z).
[[nodiscard]] scene::Scene placed(scene::Scene objects, const Placement& placement);

}  // namespace vem::view
