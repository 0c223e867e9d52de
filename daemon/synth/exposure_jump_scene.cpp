#include "synth/exposure_jump_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/env_map.h"

namespace vem::synth {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
const glm::dvec3 kGroundTint(1.0, 1.0, 1.0);
// A slightly blue grey of luminance 1 (core/color.h).
const glm::dvec3 kOvercastTint =
    glm::dvec3(0.97, 1.0, 1.06) / luminance(glm::dvec3(0.97, 1.0, 1.06));

}  // namespace

ExposureJumpScene::ExposureJumpScene(ExposureJumpParams params) : params_(params) {}

SceneState ExposureJumpScene::at(double timeS) const {
  const glm::dvec3 glowDir = directionFromAngles((90.0 - params_.glowElevationDeg) * kDegToRad,
                                                 params_.glowAzimuthDeg * kDegToRad);
  SceneState state;
  state.radiance = [p = params_, glowDir](const glm::dvec3& dir) {
    if (dir.y < 0.0) return p.groundCdM2 * kGroundTint;
    const double sky = p.zenithLuminanceCdM2 * (1.0 + 2.0 * dir.y) / 3.0;
    const double gamma = std::acos(std::clamp(glm::dot(dir, glowDir), -1.0, 1.0));
    const double g = gamma / (p.glowWidthDeg * kDegToRad);
    return (sky + p.glowLuminanceCdM2 * std::exp(-g * g)) * kOvercastTint;
  };
  state.exposureUs = timeS < params_.jumpAtS ? params_.exposureBeforeUs : params_.exposureAfterUs;
  state.gain = 1.0;
  state.sunDirWorld = glowDir;
  state.sunVisibility = 0.0;
  return state;
}

}  // namespace vem::synth
