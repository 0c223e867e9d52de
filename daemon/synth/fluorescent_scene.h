// The `fluorescent` scene: an office-like room lit only by fluorescent ceiling lamps whose light
// ripples at twice the mains frequency, the flicker a capture rate aliases into the lights.
//
// Geometry (metres, world frame of daemon/core/env_map.h, camera at the origin looking up): a box
// from -halfWidth to +halfWidth in x, -halfDepth to +halfDepth in z, floorBelow below the camera
// (a desk) to ceilingAbove above it. Four lamp panels (lampLength along x by lampWidth along z)
// sit on the ceiling centred at (+-lampSpacingX / 2, +-lampSpacingZ / 2). A direction sees the
// surface its ray meets first:
//   lamp      lampLuminanceCdM2 (warm white),
//   ceiling   ceilingCdM2,
//   walls     wallBottomCdM2 at the floor to wallTopCdM2 at the ceiling, linear in height,
//   floor     floorCdM2.
// The lamps light everything, so every surface ripples in phase with them:
//     L(t) = L (1 + rippleDepth sin(2 pi rippleHz t)),
// sampled at the frame's time (a log sensor reads continuously; a 1 ms exposure would average the
// 100 Hz ripple away by only 1.6 %). At 30 frames/s, 100 Hz aliases to |100 - 3 x 30| = 10 Hz: a
// period of exactly 3 frames, power 1, 1.26, 0.74 relative to the mean. No sun.
#pragma once

#include <string>

#include "synth/synthetic_scene.h"

namespace vem::synth {

struct FluorescentParams {
  double rippleHz = 100.0;  // twice 50 Hz mains
  double rippleDepth = 0.3;
  double lampLuminanceCdM2 = 4000.0;  // a louvred fluorescent troffer
  double ceilingCdM2 = 25.0;
  double wallTopCdM2 = 45.0;
  double wallBottomCdM2 = 20.0;
  double floorCdM2 = 12.0;
  double halfWidthM = 3.0;
  double halfDepthM = 4.0;
  double ceilingAboveM = 1.8;
  double floorBelowM = 0.8;
  double lampLengthM = 1.2;
  double lampWidthM = 0.3;
  double lampSpacingXM = 2.4;
  double lampSpacingZM = 3.0;
};

class FluorescentScene : public SyntheticScene {
 public:
  explicit FluorescentScene(FluorescentParams params = {});

  [[nodiscard]] std::string name() const override { return "fluorescent"; }
  [[nodiscard]] SceneState at(double timeS) const override;

  // 1 + rippleDepth sin(2 pi rippleHz t): every luminance's factor at time t.
  [[nodiscard]] double rippleFactor(double timeS) const;

 private:
  FluorescentParams params_;
};

}  // namespace vem::synth
