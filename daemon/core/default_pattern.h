// The default sampling patterns shared by every frame and every process: the first kMaxLights
// points of relaxedHaltonPattern (sampling_pattern.h) relaxed on each layout's surface, precomputed
// at build time and embedded in the library. Light identity i is pattern point i; N lights use the
// first N.
#pragma once

#include <cstddef>
#include <span>

#include <glm/vec2.hpp>

#include "core/env_map.h"

namespace vem {

// The most lights one set may hold (the pattern's length).
inline constexpr std::size_t kMaxLights = 65536;

[[nodiscard]] std::span<const glm::dvec2> defaultSamplingPattern(MapLayout layout);

}  // namespace vem
