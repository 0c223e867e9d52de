// PlateView: the scene camera as vemview composites with it (issue 21): the ideal pinhole camera
// the renderers draw the layers with, the turn that takes the plate's world (its floor board's)
// into the light probe's world (where the lights are), where each plate pixel lands in the render
// (the lens's distortion and the two sizes), and the colour match.
//
// - From a plate-camera file (calib/core/plate_camera.h): the intrinsics and pose of the file;
//   the probe's yaw turns the geometry, not the lights: objects, local scene and camera go into
//   the probe's world by RotY(-probeYawRad) (dir_plateWorld = RotY(probeYawRad) dir_probeWorld).
// - For the simulated plate (--plate sim): the simulated world's camera, no distortion, yaw 0,
//   gain 1.
// The render keeps the plate's aspect: renderHeightPx follows renderWidthPx.
#pragma once

#include <expected>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "calib/core/plate_camera.h"
#include "client/render/differential_composite.h"
#include "client/scene/mixed_reality_world.h"
#include "client/scene/view_camera.h"

namespace vem::view {

struct PlateView {
  scene::ViewCamera camera;                  // in the light probe's world
  glm::mat4 probeWorldFromPlateWorld{1.0F};  // for the objects and the local scene
  int plateWidthPx = 0;
  int plateHeightPx = 0;
  int renderWidthPx = 0;
  int renderHeightPx = 0;
  std::vector<glm::vec2> renderPxOfPlatePx;  // empty: no distortion (render/layer_resampling.h)
  render::PlateColour colour;
  std::string description;  // for the plan line
};

// `file` names the plate-camera file in messages. Fails in one sentence when the camera has no
// pose yet, or when the plate's size is not the size the file was calibrated at (another camera,
// or another mode of it).
[[nodiscard]] std::expected<PlateView, std::string> plateViewOf(const calib::PlateCamera& camera,
                                                                const std::string& file,
                                                                int plateWidthPx, int plateHeightPx,
                                                                int renderWidthPx);

[[nodiscard]] PlateView simulatedPlateView(const scene::MixedRealityWorld& world, int renderWidthPx,
                                           int renderHeightPx);

// How far the objects slide on the floor (y = 0, in the light probe's world) when the cursor drags
// their floor point, under `centreWorld`, by dragPlatePx (plate pixels, +y down): the floor point
// follows the cursor through the plate camera. Nothing when the point is behind the camera or the
// cursor leaves the floor (at or above the horizon). The lens's distortion is left out.
[[nodiscard]] std::optional<glm::vec3> floorMoveOfDrag(const PlateView& view, glm::vec3 centreWorld,
                                                       glm::vec2 dragPlatePx);

// The render height that keeps the plate's aspect at renderWidthPx (at least 1).
[[nodiscard]] int renderHeightFor(int plateWidthPx, int plateHeightPx, int renderWidthPx);

}  // namespace vem::view
