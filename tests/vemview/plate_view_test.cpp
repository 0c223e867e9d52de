// The plate camera as vemview composites with it (client/vemview/plate_view.h) and the composite's
// plan rule (render_plan.h's compositePlanFor).
#include "client/vemview/plate_view.h"

#include <numbers>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "client/scene/primitives.h"
#include "client/vemview/render_plan.h"

namespace vem::view {
namespace {

calib::PlateCamera levelCamera(double probeYawRad) {
  calib::PlateCamera camera;
  camera.camera.sensorWidthPx = 160;
  camera.camera.sensorHeightPx = 120;
  camera.intrinsics = {160, 120, 150.0, 150.0, 79.5, 59.5, calib::PlateLensModel::BrownConrady, {}};
  camera.pose = calib::plateLookingAt({0.0, 1.0, 3.0}, {0.0, 0.3, 0.0});
  camera.probeYawRad = probeYawRad;
  return camera;
}

TEST(PlateView, DraggingTheObjectsFloorPointMovesThemWhereTheCursorPointsOnTheFloor) {
  const PlateView view = simulatedPlateView(scene::mixedRealityWorld(), 160, 120);
  const glm::vec3 centre(-0.1F, 0.3F, 0.1F);
  const glm::vec3 wanted(0.4F, 0.0F, -0.3F);
  const auto at = [&](glm::vec3 p) {
    return view.camera.project(glm::vec3(p.x, 0.0F, p.z), 160, 120).pixel;
  };
  const std::optional<glm::vec3> move =
      floorMoveOfDrag(view, centre, at(centre + wanted) - at(centre));
  ASSERT_TRUE(move.has_value());
  EXPECT_NEAR(move->x, wanted.x, 1e-3F);
  EXPECT_NEAR(move->y, 0.0F, 1e-6F);
  EXPECT_NEAR(move->z, wanted.z, 1e-3F);
  // Dragged above the horizon: no floor there, no move.
  EXPECT_FALSE(floorMoveOfDrag(view, centre, glm::vec2(0.0F, -400.0F)).has_value());
}

TEST(PlateView, ProbeYawTurnsTheSceneNotTheLightsSoAPlateDirectionMeetsItsProbeDirection) {
  // dir_plate = RotY(yaw) dir_probe: what the plate camera sees along dir_plate, the renderers
  // (in the probe's world) must see along RotY(-yaw) dir_plate.
  const double yawRad = 0.6;
  auto turned = plateViewOf(levelCamera(yawRad), "plate.toml", 160, 120, 160);
  auto level = plateViewOf(levelCamera(0.0), "plate.toml", 160, 120, 160);
  ASSERT_TRUE(turned.has_value() && level.has_value());
  const scene::Ray plateRay = level->camera.primaryRay(40.5F, 30.5F, 160, 120);
  const scene::Ray probeRay = turned->camera.primaryRay(40.5F, 30.5F, 160, 120);
  const glm::vec3 expected =
      glm::vec3(glm::rotate(glm::mat4(1.0F), float(-yawRad), glm::vec3(0.0F, 1.0F, 0.0F)) *
                glm::vec4(plateRay.dirWorld, 0.0F));
  EXPECT_GT(glm::dot(probeRay.dirWorld, expected), 1.0F - 1e-5F);
}

TEST(PlateView, FileOfAnotherSizeOrWithoutAPoseIsOneSentenceNamingTheField) {
  auto otherSize = plateViewOf(levelCamera(0.0), "plate.toml", 320, 240, 160);
  ASSERT_FALSE(otherSize.has_value());
  EXPECT_NE(otherSize.error().find("plate.toml: intrinsics: calibrated for 160 x 120"),
            std::string::npos)
      << otherSize.error();
  calib::PlateCamera noPose = levelCamera(0.0);
  noPose.pose.reset();
  auto missing = plateViewOf(noPose, "plate.toml", 160, 120, 160);
  ASSERT_FALSE(missing.has_value());
  EXPECT_NE(missing.error().find("plate.toml: pose: missing"), std::string::npos)
      << missing.error();
}

TEST(RenderPlan, CompositeSkipsTheDifferentialPassWhenNothingSyntheticCanShadowTheFloor) {
  EXPECT_FALSE(compositePlanFor(scene::Scene{}, 2).differential);
  scene::Scene below;
  below.materials.push_back(scene::Material{});
  below.meshes.push_back(scene::sphereMesh({0.0F, -2.0F, 0.0F}, 0.5F, 8, 16));
  const CompositePlan under = compositePlanFor(below, 0);
  EXPECT_FALSE(under.differential);
  EXPECT_NE(under.reason.find("below the floor"), std::string::npos) << under.reason;
  EXPECT_TRUE(compositePlanFor(below, 1).differential);  // a proxy it may still shadow
  scene::Scene above = below;
  above.meshes[0] = scene::sphereMesh({0.0F, 0.5F, 0.0F}, 0.5F, 8, 16);
  EXPECT_TRUE(compositePlanFor(above, 0).differential);
}

}  // namespace
}  // namespace vem::view
