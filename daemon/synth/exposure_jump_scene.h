// The `exposure-jump` scene: a steady overcast sky while the camera's exposure changes suddenly,
// as an auto-exposure step would. The world does not change; only SceneState::exposureUs does.
//
// Sky: the CIE overcast sky, L(theta) = zenithLuminanceCdM2 (1 + 2 cos theta) / 3, plus a soft
// glow where the sun hides behind the overcast (glowLuminanceCdM2 x exp(-(gamma / glowWidth)^2),
// gamma the angle from the glow's centre at glowElevationDeg, glowAzimuthDeg), over a grey ground
// of groundCdM2. sunDirWorld is the glow's centre, sunVisibility 0 (the sun itself is not seen).
// Exposure: exposureBeforeUs until jumpAtS, exposureAfterUs from then on (gain 1).
//
// What a camera makes of it depends on its response (calib/core/photometric_model.h): a linear
// camera's codes above black scale with the exposure (x 1/4 with the defaults), while a log sensor
// such as the example camera has no exposure and its codes do not change at all. Either way, the
// calibrated map (codes through the response at each frame's own exposure) stays the same.
// Luminances 6.7 to 60 cd/m^2 suit a linear 12-bit camera at both exposures, and the example one.
#pragma once

#include <string>

#include "synth/synthetic_scene.h"

namespace vem::synth {

struct ExposureJumpParams {
  double zenithLuminanceCdM2 = 20.0;
  double glowLuminanceCdM2 = 40.0;
  double glowWidthDeg = 12.0;
  double glowElevationDeg = 40.0;
  double glowAzimuthDeg = 90.0;
  double groundCdM2 = 4.0;
  double jumpAtS = 1.0;
  double exposureBeforeUs = 1000.0;
  double exposureAfterUs = 250.0;
};

class ExposureJumpScene : public SyntheticScene {
 public:
  explicit ExposureJumpScene(ExposureJumpParams params = {});

  [[nodiscard]] std::string name() const override { return "exposure-jump"; }
  [[nodiscard]] SceneState at(double timeS) const override;

 private:
  ExposureJumpParams params_;
};

}  // namespace vem::synth
