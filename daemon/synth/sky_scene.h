// The `sky` scene: a clear sky (Preetham, preetham_sky.h) with a sun disc moving along an arc, and
// a uniform ground below the horizon. docs/synthetic-scenes.md gives the numbers and their reasons.
//
// Luminances are scaled to the example log camera (config/camera-example.toml reads 8e-4 to 1.6e5
// cd/m^2): the zenith is 1 cd/m^2 (the sky spans about 0.7 to 8 cd/m^2 at turbidity 3, brightest
// around the sun and at the horizon) and the sun disc 1e5 cd/m^2, a factor 1.6 below the camera's
// saturation (its codes about 3970 of 4095). The sun-to-zenith ratio is 1e5 whatever the sun's
// height (in nature, about 2e5 at 45 degrees: 1.6e9 against 7e3 cd/m^2; both fall toward sunset).
// The sun's power (1e5 cd/m^2 x 6.7e-5 sr) is 36 % (sun low) to 48 % (sun high) of all the light.
//
// The sun's path is the equinox sun's at latitude `latitudeDeg`: a great circle through the east
// (+X, phi = 0) and west (-X) horizon points, tilted toward the south (+Z, phi = 90 degrees) so
// that it culminates at elevation 90 - latitude. Its arc angle alpha (0 = east horizon, 90 = noon,
// 180 = west horizon) runs at `speedDegPerS` from `startDeg` and turns back at `lowDeg` and
// `highDeg` (a triangle wave), so the sun stays up and moves continuously:
//     sunDir = cos(alpha) (1, 0, 0) + sin(alpha) (0, cos(latitude), sin(latitude)).
// The default, 1 degree per second, is a 240x time lapse of the real sun (15 degrees per hour).
//
// Ground: albedo x (horizontal illuminance of sun and sky) / pi, a Lambertian plain lit by them.
#pragma once

#include <memory>
#include <string>

#include <glm/vec3.hpp>

#include "synth/preetham_sky.h"
#include "synth/synthetic_scene.h"

namespace vem::synth {

struct SunArc {
  double latitudeDeg = 40.0;  // the arc culminates at elevation 90 - latitude
  double startDeg = 30.0;     // arc angle at t = 0 (elevation 22.5 degrees, east-south-east)
  double speedDegPerS = 1.0;  // arc degrees per second
  double lowDeg = 20.0;       // it turns back here (elevation 15.2 degrees) ...
  double highDeg = 160.0;     // ... and here
};

// The arc angle (degrees) and the unit direction toward the sun at time t.
[[nodiscard]] double sunArcAngleDeg(const SunArc& arc, double timeS);
[[nodiscard]] glm::dvec3 sunDirection(const SunArc& arc, double timeS);

struct SkyParams {
  double turbidity = 3.0;
  double zenithLuminanceCdM2 = 1.0;
  double sunLuminanceCdM2 = 1.0e5;
  double sunDiameterDeg = 0.53;
  glm::dvec3 sunTint{1.0, 0.96, 0.88};  // the sun's colour (scaled to sunLuminanceCdM2)
  glm::dvec3 groundAlbedo{0.20, 0.18, 0.15};
  SunArc arc;
};

// The clear sky at one instant, by world direction (cd/m^2 per channel).
struct ClearSkyInstant {
  std::shared_ptr<const PreethamSky> model;
  PreethamSky::SunTerms sun;
  glm::dvec3 sunRgb{0.0};  // inside the disc, before any occlusion
  double cosSunRadius = 1.0;
  glm::dvec3 groundRgb{0.0};

  // The sky above the horizon, the ground below it; without the sun disc.
  [[nodiscard]] glm::dvec3 skyOrGround(const glm::dvec3& dir) const;
  // sunRgb inside the disc, else 0.
  [[nodiscard]] glm::dvec3 sunDisc(const glm::dvec3& dir) const;
};

class SkyScene : public SyntheticScene {
 public:
  explicit SkyScene(SkyParams params = {});

  [[nodiscard]] std::string name() const override { return "sky"; }
  [[nodiscard]] SceneState at(double timeS) const override;

  // The sky at time t, its ground lit by the sun times `sunVisibility` (the cloud scene's
  // occlusion) and by the clear sky.
  [[nodiscard]] ClearSkyInstant instant(double timeS, double sunVisibility = 1.0) const;
  [[nodiscard]] const SkyParams& params() const { return params_; }

 private:
  SkyParams params_;
  std::shared_ptr<const PreethamSky> model_;
};

}  // namespace vem::synth
