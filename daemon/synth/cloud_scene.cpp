#include "synth/cloud_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "synth/value_noise.h"

namespace vem::synth {
namespace {

constexpr double kHorizonFadeY = 0.1;  // sin(5.7 degrees): clouds fade out below
constexpr double kMinLayerY = 0.02;    // directions lower than this meet the layer here
constexpr double kThickRange = 0.25;   // noise above threshold over which a cloud thickens
const double kSilverWidth = 1.0 - std::cos(10.0 * std::numbers::pi / 180.0);

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

struct CloudSample {
  double opacity = 0.0;
  double thickness = 0.0;
};

CloudSample sampleClouds(const CloudParams& p, const ValueNoise& noiseField, const glm::dvec3& dir,
                         double timeS) {
  if (dir.y <= 0.0) return {};
  const double y = std::max(dir.y, kMinLayerY);
  const glm::dvec2 onLayer = glm::dvec2(dir.x, dir.z) / y;
  const glm::dvec2 field = (onLayer - p.windPerS * timeS) / p.featureSize;
  const double noise = noiseField.fractal(field, p.octaves);
  const double fadeOut = smoothstep(0.0, kHorizonFadeY, dir.y);
  return {fadeOut * smoothstep(p.threshold - p.edgeSoftness, p.threshold + p.edgeSoftness, noise),
          smoothstep(p.threshold, p.threshold + kThickRange, noise)};
}

}  // namespace

CloudScene::CloudScene(CloudParams params)
    : params_(params), sky_(params.sky), noise_(std::make_shared<const ValueNoise>(params.seed)) {}

double CloudScene::opacity(const glm::dvec3& dir, double timeS) const {
  return sampleClouds(params_, *noise_, dir, timeS).opacity;
}

SceneState CloudScene::at(double timeS) const {
  const glm::dvec3 sunDir = sunDirection(params_.sky.arc, timeS);
  const double visibility = 1.0 - opacity(sunDir, timeS);
  SceneState state;
  state.radiance = [p = params_, noise = noise_, sky = sky_.instant(timeS, visibility),
                    timeS](const glm::dvec3& dir) {
    const CloudSample cloud = sampleClouds(p, *noise, dir, timeS);
    if (cloud.opacity <= 0.0) return sky.skyOrGround(dir) + sky.sunDisc(dir);
    const double towardSun = 1.0 - glm::dot(dir, sky.sun.sunDir);
    const glm::dvec3 lit(p.cloudLuminanceCdM2 * (1.0 - 0.5 * cloud.thickness) *
                         (1.0 + p.silverLining * std::exp(-towardSun / kSilverWidth)));
    if (cloud.opacity >= 1.0) return lit;  // the sky behind is hidden: not worth computing
    return (1.0 - cloud.opacity) * (sky.skyOrGround(dir) + sky.sunDisc(dir)) + cloud.opacity * lit;
  };
  state.sunDirWorld = sunDir;
  state.sunVisibility = visibility;
  return state;
}

}  // namespace vem::synth
