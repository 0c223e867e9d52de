// MapRadiance: radiance from an environment map by world direction, for the hdri scene and
// `vemtool import`. The lookup of calib::radianceFromMap (calib/core/camera_simulator.h), made
// cheaper per call: the same pixel geometry (daemon/core/env_map.h), bilinear interpolation between
// pixel centres, wrapping around the azimuth and clamping at the poles (or the hemisphere's
// horizon), 0 for directions outside the layout; but the angles in float (acosf, atan2f: 1e-6 rad)
// and the map sanitised once (NaN, infinite and negative channels read 0 before interpolation,
// where radianceFromMap zeroes the interpolated result).
#pragma once

#include <memory>

#include <glm/vec3.hpp>

#include "core/env_map.h"

namespace vem::synth {

class MapRadiance {
 public:
  // `scale` multiplies every value (the map's units to cd/m^2).
  explicit MapRadiance(const EnvMap& map, double scale = 1.0);

  [[nodiscard]] glm::dvec3 operator()(const glm::dvec3& dirWorld) const;

 private:
  std::shared_ptr<const EnvMap> map_;  // sanitised and scaled; shared by copies
  float thetaMaxRad_ = 0.0F;
};

}  // namespace vem::synth
