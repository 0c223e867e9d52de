#include "synth/sky_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/env_map.h"

namespace vem::synth {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Horizontal irradiance of the sky alone (cd/m^2 x sr per channel): the midpoint rule over a
// 16 x 48 grid of the upper hemisphere, weighted by cos theta.
glm::dvec3 skyIrradiance(const PreethamSky& model, const PreethamSky::SunTerms& sun) {
  constexpr int kRows = 16;
  constexpr int kColumns = 48;
  const double dTheta = 0.5 * std::numbers::pi / kRows;
  const double dPhi = 2.0 * std::numbers::pi / kColumns;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kRows; ++i) {
    const double theta = (i + 0.5) * dTheta;
    const double weight = std::cos(theta) * std::sin(theta) * dTheta * dPhi;
    for (int j = 0; j < kColumns; ++j) {
      sum += weight * model.radiance(sun, directionFromAngles(theta, (j + 0.5) * dPhi));
    }
  }
  return sum;
}

}  // namespace

double sunArcAngleDeg(const SunArc& arc, double timeS) {
  const double span = arc.highDeg - arc.lowDeg;
  if (!(span > 0.0)) return arc.lowDeg;
  // Distance travelled from lowDeg, folded into [0, 2 span): out along the arc, then back.
  const double travelled =
      std::fmod(arc.startDeg - arc.lowDeg + arc.speedDegPerS * timeS, 2 * span);
  const double folded = travelled < 0.0 ? travelled + 2 * span : travelled;
  return arc.lowDeg + (folded <= span ? folded : 2 * span - folded);
}

glm::dvec3 sunDirection(const SunArc& arc, double timeS) {
  const double alpha = sunArcAngleDeg(arc, timeS) * kDegToRad;
  const double latitude = arc.latitudeDeg * kDegToRad;
  const glm::dvec3 east(1.0, 0.0, 0.0);
  const glm::dvec3 noon(0.0, std::cos(latitude), std::sin(latitude));
  return glm::normalize(std::cos(alpha) * east + std::sin(alpha) * noon);
}

glm::dvec3 ClearSkyInstant::skyOrGround(const glm::dvec3& dir) const {
  return dir.y >= 0.0 ? model->radiance(sun, dir) : groundRgb;
}

glm::dvec3 ClearSkyInstant::sunDisc(const glm::dvec3& dir) const {
  return glm::dot(dir, sun.sunDir) >= cosSunRadius ? sunRgb : glm::dvec3(0.0);
}

SkyScene::SkyScene(SkyParams params)
    : params_(params), model_(std::make_shared<const PreethamSky>(params.turbidity)) {}

ClearSkyInstant SkyScene::instant(double timeS, double sunVisibility) const {
  ClearSkyInstant sky;
  sky.model = model_;
  sky.sun = model_->sunTerms(sunDirection(params_.arc, timeS), params_.zenithLuminanceCdM2);
  sky.sunRgb = params_.sunTint * (params_.sunLuminanceCdM2 / luminance(params_.sunTint));
  const double radius = 0.5 * params_.sunDiameterDeg * kDegToRad;
  sky.cosSunRadius = std::cos(radius);
  const double sunSolidAngleSr = 2.0 * std::numbers::pi * (1.0 - sky.cosSunRadius);
  const glm::dvec3 irradiance = skyIrradiance(*model_, sky.sun) +
                                sky.sunRgb * (sunSolidAngleSr * sky.sun.sunDir.y * sunVisibility);
  sky.groundRgb = params_.groundAlbedo * irradiance / std::numbers::pi;
  return sky;
}

SceneState SkyScene::at(double timeS) const {
  SceneState state;
  const ClearSkyInstant sky = instant(timeS);
  state.radiance = [sky](const glm::dvec3& dir) { return sky.skyOrGround(dir) + sky.sunDisc(dir); };
  state.sunDirWorld = sky.sun.sunDir;
  state.sunVisibility = 1.0;
  return state;
}

}  // namespace vem::synth
