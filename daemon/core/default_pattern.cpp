#include "core/default_pattern.h"

namespace vem {
namespace detail {
// Generated at build time by vem_pattern_gen: x, y pairs, kMaxLights points each.
extern const double kEmbeddedSpherePattern[];
extern const double kEmbeddedHemispherePattern[];
}  // namespace detail

std::span<const glm::dvec2> defaultSamplingPattern(MapLayout layout) {
  static_assert(sizeof(glm::dvec2) == 2 * sizeof(double));
  const double* data = layout == MapLayout::Sphere ? detail::kEmbeddedSpherePattern
                                                   : detail::kEmbeddedHemispherePattern;
  return {reinterpret_cast<const glm::dvec2*>(data), kMaxLights};
}

}  // namespace vem
