#include "client/render/soft_shadows.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "client/render/cube_map_sampling.h"
#include "core/color.h"

namespace vem::render {

std::vector<float> shadowConeSolidAnglesSr(std::span<const Light> lights, const CubeMap& cube) {
  std::vector<float> out(lights.size(), 0.0F);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const double radiance = luminance(sampleCubeMap(cube, lights[i].dir));
    const double irradiance = luminance(lights[i].rgb);
    if (!(radiance > 0.0) || !std::isfinite(radiance) || !std::isfinite(irradiance)) continue;
    const double solidAngleSr = irradiance / radiance;
    if (solidAngleSr < double(kSoftShadowMinSr)) continue;
    out[i] = float(std::min(solidAngleSr, double(kSoftShadowMaxSr)));
  }
  return out;
}

float coneCosineOf(float solidAngleSr) {
  return 1.0F - solidAngleSr / (2.0F * std::numbers::pi_v<float>);
}

}  // namespace vem::render
