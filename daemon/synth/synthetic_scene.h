// Synthetic scenes: environments that change over time with a known truth, for synthetic
// recordings (`vemtool synth`), the daemon's `synthetic:SCENE` source, tests and benchmarks.
// A scene says what the world looks like at time t; a SyntheticCamera (synthetic_camera.h) turns
// that into the raw frame a calibrated camera would deliver (through calib's camera simulator).
//
// Conventions: world frame and directions as daemon/core/env_map.h (+Y up); radiance in cd/m^2 per
// channel (linear Rec. 709 RGB); time in seconds from the scene's start; exposure in microseconds.
// Scenes are pure and deterministic: the same time gives the same state.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "calib/core/camera_simulator.h"

namespace vem::synth {

// The world at one instant, and how the camera is set for it.
struct SceneState {
  calib::RadianceFunction radiance;  // cd/m^2 per channel, by world direction
  double exposureUs = 1000.0;
  double gain = 1.0;
  std::optional<glm::dvec3> sunDirWorld;  // unit, toward the sun, when the scene has one
  double sunVisibility = 1.0;             // 0 (hidden by cloud) to 1 (clear), when it has one
};

class SyntheticScene {
 public:
  virtual ~SyntheticScene() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual SceneState at(double timeS) const = 0;
};

}  // namespace vem::synth
