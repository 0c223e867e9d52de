// Irradiance at a surface normal (world frame of env_map.h), for accuracy figures and tests:
// E(n) = integral of L(w) max(0, n . w) dw, per channel.
// - irradianceFromMap sums every pixel: L (sanitised) x pixel solid angle x max(0, n . pixel
// centre).
//   This is the exact integral of the piecewise-constant map up to the cosine's variation within a
//   pixel (second order in the pixel size), the reference for the lights.
// - irradianceFromLights sums rgb_i max(0, n . dir_i).
// relativeRmsError is sqrt(mean |E_lights - E_exact|^2) / sqrt(mean |E_exact|^2) over the normals,
// on luminance: robust where some normals face a dark half of the map.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/env_map.h"
#include "core/light.h"

namespace vem {

[[nodiscard]] std::vector<glm::dvec3> irradianceFromMap(const EnvMap& map,
                                                        std::span<const glm::dvec3> normals);
[[nodiscard]] std::vector<glm::dvec3> irradianceFromLights(std::span<const Light> lights,
                                                           std::span<const glm::dvec3> normals);
[[nodiscard]] double relativeRmsError(std::span<const glm::dvec3> estimate,
                                      std::span<const glm::dvec3> reference);

}  // namespace vem
