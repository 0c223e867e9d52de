#include "synth/hdri_scene.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "util/contract.h"

namespace vem::synth {

HdriScene::HdriScene(const EnvMap& map, std::string mapName, HdriParams params)
    : lookup_(map, params.scale), mapName_(std::move(mapName)), params_(params) {
  VEM_EXPECTS(map.width > 0 && map.height > 0);
}

double HdriScene::panAngleRad(double timeS) const {
  return params_.panDegPerS * timeS * std::numbers::pi / 180.0;
}

SceneState HdriScene::at(double timeS) const {
  const double angle = panAngleRad(timeS);
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  SceneState state;
  // The map's direction seen now toward dir: phi turned back by the pan angle.
  state.radiance = [lookup = lookup_, c, s](const glm::dvec3& dir) {
    return lookup(glm::dvec3(dir.x * c + dir.z * s, dir.y, dir.z * c - dir.x * s));
  };
  return state;
}

}  // namespace vem::synth
