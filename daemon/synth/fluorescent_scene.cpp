#include "synth/fluorescent_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/color.h"

namespace vem::synth {
namespace {

// Colours with luminance 1 (core/color.h), times each surface's luminance.
glm::dvec3 tint(double r, double g, double b) { return glm::dvec3(r, g, b) / luminance(r, g, b); }

const glm::dvec3 kLampTint = tint(1.0, 0.95, 0.84);   // about 4000 K
const glm::dvec3 kPaintTint = tint(1.0, 0.97, 0.92);  // warm white walls and ceiling
const glm::dvec3 kFloorTint = tint(0.85, 0.80, 0.74);

// Distance along `dir` to the plane where coordinate `component` reaches +-bound (infinite when the
// ray runs parallel to it).
double distanceToWall(double component, double bound) {
  if (component == 0.0) return std::numeric_limits<double>::infinity();
  return (component > 0.0 ? bound : -bound) / component;
}

bool onLamp(const FluorescentParams& p, double x, double z) {
  return std::abs(std::abs(x) - 0.5 * p.lampSpacingXM) <= 0.5 * p.lampLengthM &&
         std::abs(std::abs(z) - 0.5 * p.lampSpacingZM) <= 0.5 * p.lampWidthM;
}

// The room's radiance toward `dir` at full lamp output (ripple factor 1).
glm::dvec3 roomRadiance(const FluorescentParams& p, const glm::dvec3& dir) {
  const double toWallX = distanceToWall(dir.x, p.halfWidthM);
  const double toWallZ = distanceToWall(dir.z, p.halfDepthM);
  const double toWall = std::min(toWallX, toWallZ);
  if (dir.y > 0.0) {
    const double toCeiling = p.ceilingAboveM / dir.y;
    if (toCeiling <= toWall) {
      const bool lamp = onLamp(p, dir.x * toCeiling, dir.z * toCeiling);
      return lamp ? p.lampLuminanceCdM2 * kLampTint : p.ceilingCdM2 * kPaintTint;
    }
  } else if (dir.y < 0.0 && -p.floorBelowM / dir.y <= toWall) {
    return p.floorCdM2 * kFloorTint;
  }
  const double height = dir.y * toWall;  // relative to the camera
  const double up =
      std::clamp((height + p.floorBelowM) / (p.floorBelowM + p.ceilingAboveM), 0.0, 1.0);
  return (p.wallBottomCdM2 + (p.wallTopCdM2 - p.wallBottomCdM2) * up) * kPaintTint;
}

}  // namespace

FluorescentScene::FluorescentScene(FluorescentParams params) : params_(params) {}

double FluorescentScene::rippleFactor(double timeS) const {
  return 1.0 + params_.rippleDepth * std::sin(2.0 * std::numbers::pi * params_.rippleHz * timeS);
}

SceneState FluorescentScene::at(double timeS) const {
  SceneState state;
  state.radiance = [p = params_, factor = rippleFactor(timeS)](const glm::dvec3& dir) {
    return factor * roomRadiance(p, dir);
  };
  return state;
}

}  // namespace vem::synth
