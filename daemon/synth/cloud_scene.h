// The `clouds` scene: the `sky` scene (sky_scene.h) under a layer of procedural clouds that drifts
// with the wind and passes over the sun.
//
// The cloud layer is a plane one unit above the camera: a direction d (d.y > 0) meets it at
// (d.x, d.z) / d.y, where the cloud field is fractal value noise (value_noise.h) of cell
// `featureSize` (repeating every 256 cells), moving at `windPerS` (layer heights per second).
// Noise above `threshold` is cloud:
//     opacity = smoothstep(threshold - edgeSoftness, threshold + edgeSoftness, noise),
// faded out toward the horizon (below about 6 degrees of elevation) where the layer would alias.
// A pixel shows
//     (1 - opacity) (sky + sun disc) + opacity cloud,
// the cloud grey-white at cloudLuminanceCdM2, darker in its thick core (down to half) and brighter
// toward the sun (forward scattering: up to 1 + silverLining times within about 10 degrees).
// sunVisibility is 1 - opacity toward the sun's centre; the ground is lit by the sun times it.
// With the defaults about half the sky is cloud and a cloud crosses the sun every few seconds.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "synth/sky_scene.h"
#include "synth/value_noise.h"

namespace vem::synth {

struct CloudParams {
  SkyParams sky = [] {
    SkyParams p;
    p.arc.startDeg = 60.0;  // the sun at 41.6 degrees of elevation at t = 0
    return p;
  }();
  double threshold = 0.5;
  double edgeSoftness = 0.08;
  double featureSize = 0.8;
  glm::dvec2 windPerS{0.25, 0.08};
  double cloudLuminanceCdM2 = 3.0;
  double silverLining = 4.0;
  int octaves = 4;
  std::uint64_t seed = 1;
};

class CloudScene : public SyntheticScene {
 public:
  explicit CloudScene(CloudParams params = {});

  [[nodiscard]] std::string name() const override { return "clouds"; }
  [[nodiscard]] SceneState at(double timeS) const override;

  // Cloud opacity in [0, 1] toward `dir` at time t.
  [[nodiscard]] double opacity(const glm::dvec3& dir, double timeS) const;

 private:
  CloudParams params_;
  SkyScene sky_;
  std::shared_ptr<const ValueNoise> noise_;
};

}  // namespace vem::synth
