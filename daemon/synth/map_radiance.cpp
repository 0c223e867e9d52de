#include "synth/map_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vem::synth {

MapRadiance::MapRadiance(const EnvMap& map, double scale)
    : thetaMaxRad_(float(thetaMaxRad(map.layout))) {
  EnvMap clean = map;
  const auto factor = float(scale);
  for (float& value : clean.rgb)
    value = std::isfinite(value) && value > 0.0F ? value * factor : 0.0F;
  map_ = std::make_shared<const EnvMap>(std::move(clean));
}

glm::dvec3 MapRadiance::operator()(const glm::dvec3& dirWorld) const {
  const EnvMap& map = *map_;
  const float theta = std::acos(std::clamp(float(dirWorld.y), -1.0F, 1.0F));
  if (theta > thetaMaxRad_ || map.width <= 0) return glm::dvec3(0.0);
  const float phi = std::atan2(float(dirWorld.z), float(dirWorld.x));  // [-pi, pi]
  constexpr float kTwoPi = 2.0F * std::numbers::pi_v<float>;
  // Column and row coordinates (env_map.h), relative to pixel centres.
  const float u = map.layout == MapLayout::Sphere ? phi / kTwoPi + 0.5F
                                                  : (phi < 0.0F ? phi + kTwoPi : phi) / kTwoPi;
  const float fx = u * float(map.width) - 0.5F;
  const float fy =
      std::clamp(theta / thetaMaxRad_ * float(map.height) - 0.5F, 0.0F, float(map.height - 1));
  const int x0 = int(fx + 1.0F) - 1;  // floor: fx >= -0.5, and no call into libm
  const float tx = fx - float(x0);
  const auto y0 = std::min(int(fy), map.height - 1);
  const int y1 = std::min(y0 + 1, map.height - 1);
  const float ty = fy - float(y0);
  // x0 lies in [-1, W - 1]: the seam's left tap wraps to the last column, the right one to 0.
  const int xa = x0 < 0 ? map.width - 1 : std::min(x0, map.width - 1);
  const int xb = xa + 1 == map.width ? 0 : xa + 1;
  const float* rgb = map.rgb.data();
  const auto pixel = [&](int x, int y) {
    return rgb + 3 * (std::size_t(y) * std::size_t(map.width) + std::size_t(x));
  };
  const float* p00 = pixel(xa, y0);
  const float* p10 = pixel(xb, y0);
  const float* p01 = pixel(xa, y1);
  const float* p11 = pixel(xb, y1);
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const float top = p00[c] + (p10[c] - p00[c]) * tx;
    const float bottom = p01[c] + (p11[c] - p01[c]) * tx;
    out[c] = double(top + (bottom - top) * ty);
  }
  return out;
}

}  // namespace vem::synth
