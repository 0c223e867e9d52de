// The `hdri:FILE` scene: a real environment map (an HDRI, any EnvMap layout) turning about the
// vertical axis, as a camera panning on a turntable would see it.
//
// Rotation: at time t a feature seen at azimuth phi at t = 0 is seen at phi + panDegPerS t (phi
// as daemon/core/env_map.h: from +X toward +Z); theta is unchanged. So
//     radiance_t(theta, phi) = scale * map(theta, phi - panDegPerS t),
// looked up bilinearly (map_radiance.h, calib::radianceFromMap's lookup). The map's values times
// `scale` are cd/m^2 per channel; scale 1 suits the shared HDRIs (skies of about 1 to 10, suns up
// to 2e4) and the example log camera. No sun is declared (sunDirWorld is empty): the map's own sun,
// if any, turns with it.
#pragma once

#include <memory>
#include <string>

#include "core/env_map.h"
#include "synth/map_radiance.h"
#include "synth/synthetic_scene.h"

namespace vem::synth {

struct HdriParams {
  double scale = 1.0;
  double panDegPerS = 10.0;
};

class HdriScene : public SyntheticScene {
 public:
  // `map` must be non-empty; `mapName` names it (the file), for name().
  HdriScene(const EnvMap& map, std::string mapName, HdriParams params = {});

  [[nodiscard]] std::string name() const override { return "hdri:" + mapName_; }
  [[nodiscard]] SceneState at(double timeS) const override;

  // The azimuth (radians) by which the map has turned at time t.
  [[nodiscard]] double panAngleRad(double timeS) const;

 private:
  MapRadiance lookup_;
  std::string mapName_;
  HdriParams params_;
};

}  // namespace vem::synth
