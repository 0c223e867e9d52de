#include "client/vemview/composite_setup.h"

#include <numbers>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "calib/io/plate_camera_file.h"
#include "client/scene/mixed_reality_world.h"
#include "client/vemview/scene_argument.h"
#include "client/vemview/simulated_plate.h"

namespace vem::view {
namespace {

scene::Scene transformed(scene::Scene s, const glm::mat4& transform) {
  const glm::mat3 linear(transform);
  const glm::mat3 normals = glm::transpose(glm::inverse(linear));
  for (scene::Mesh& mesh : s.meshes) {
    for (glm::vec3& p : mesh.positions) p = glm::vec3(transform * glm::vec4(p, 1.0F));
    for (glm::vec3& n : mesh.normals) n = glm::normalize(normals * n);
  }
  return s;
}

}  // namespace

scene::Scene placed(scene::Scene objects, const Placement& placement) {
  const glm::mat4 move =
      glm::translate(glm::mat4(1.0F),
                     glm::vec3(float(placement.xM), float(placement.yM), float(placement.zM))) *
      glm::rotate(glm::mat4(1.0F), float(placement.yawDeg * std::numbers::pi / 180.0),
                  glm::vec3(0.0F, 1.0F, 0.0F));
  return transformed(std::move(objects), move);
}

std::expected<CompositeSetup, std::string> setUpComposite(const ViewerOptions& options,
                                                          const scene::Scene& objectsAsGiven,
                                                          const InputFrame& firstInput) {
  CompositeSetup setup;
  const scene::MixedRealityWorld world = scene::mixedRealityWorld();
  scene::Scene local = scene::floorOnly();
  std::size_t proxies = 0;
  if (!options.localScene.empty()) {
    auto loaded = loadSceneArgument(options.localScene, options.sceneAllowOutside);
    if (!loaded) return std::unexpected("--local-scene: " + loaded.error());
    for (const scene::Mesh& mesh : loaded->meshes) local.meshes.push_back(mesh);
    proxies = loaded->meshes.size();
  }
  if (options.plate == "sim") {
    if (firstInput.map == nullptr) {
      return std::unexpected(
          "--plate sim renders the simulated world under an environment map, and the input "
          "has none: give --map FILE");
    }
    if (options.localScene.empty()) {  // the simulated world's own proxies
      for (const scene::Mesh& mesh : world.proxies.meshes) local.meshes.push_back(mesh);
      proxies = world.proxies.meshes.size();
    }
    const int heightPx =
        renderHeightFor(world.intrinsics.widthPx, world.intrinsics.heightPx, options.widthPx);
    auto plate = openSimulatedPlate(world, *firstInput.map, options.widthPx, heightPx);
    if (!plate) return std::unexpected(plate.error());
    setup.plate = std::move(*plate);
    setup.view = simulatedPlateView(world, options.widthPx, heightPx);
  } else {
    auto camera = calib::io::loadPlateCameraFile(options.plateCamera);
    if (!camera) return std::unexpected(camera.error().message);
    auto plate = openPlateSource(options.plate);
    if (!plate) return std::unexpected(plate.error());
    setup.plate = std::move(*plate);
    auto view = plateViewOf(*camera, options.plateCamera, setup.plate->widthPx(),
                            setup.plate->heightPx(), options.widthPx);
    if (!view) return std::unexpected(view.error());
    setup.view = std::move(*view);
  }
  const scene::Scene objects =
      options.place ? placed(objectsAsGiven, *options.place) : objectsAsGiven;
  setup.plan = compositePlanFor(objects, proxies);
  setup.plan.plate = setup.plate->description();
  setup.plan.camera = setup.view.description;
  const scene::Scene turned = transformed(objects, setup.view.probeWorldFromPlateWorld);
  if (!turned.meshes.empty()) setup.plan.objectBounds = scene::sceneBounds(turned);
  setup.composition =
      scene::composeWithLocal(turned, transformed(local, setup.view.probeWorldFromPlateWorld));
  return setup;
}

}  // namespace vem::view
