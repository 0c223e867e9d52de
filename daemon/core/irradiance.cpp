#include "core/irradiance.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/sampling_tables.h"
#include "util/contract.h"

namespace vem {

std::vector<glm::dvec3> irradianceFromMap(const EnvMap& map, std::span<const glm::dvec3> normals) {
  std::vector<glm::dvec3> result(normals.size(), glm::dvec3(0));
  for (int y = 0; y < map.height; ++y) {
    const double omega = pixelSolidAngleSr(map.layout, map.width, map.height, y);
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 radianceSr = omega * sanitizedRgb(map, x, y);
      const glm::dvec3 dir = pixelCentreDirection(map, x, y);
      for (std::size_t i = 0; i < normals.size(); ++i) {
        result[i] += radianceSr * std::max(0.0, glm::dot(normals[i], dir));
      }
    }
  }
  return result;
}

std::vector<glm::dvec3> irradianceFromLights(std::span<const Light> lights,
                                             std::span<const glm::dvec3> normals) {
  std::vector<glm::dvec3> result(normals.size(), glm::dvec3(0));
  for (const Light& light : lights) {
    for (std::size_t i = 0; i < normals.size(); ++i) {
      result[i] +=
          glm::dvec3(light.rgb) * std::max(0.0, glm::dot(normals[i], glm::dvec3(light.dir)));
    }
  }
  return result;
}

double relativeRmsError(std::span<const glm::dvec3> estimate,
                        std::span<const glm::dvec3> reference) {
  VEM_EXPECTS(estimate.size() == reference.size());
  double errorSq = 0;
  double referenceSq = 0;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const double e = luminance(estimate[i]) - luminance(reference[i]);
    errorSq += e * e;
    referenceSq += luminance(reference[i]) * luminance(reference[i]);
  }
  return referenceSq > 0 ? std::sqrt(errorSq / referenceSq) : std::sqrt(errorSq);
}

}  // namespace vem
