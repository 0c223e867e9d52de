// From an environment map to N directional lights (paper 004 section 3): each point of the sampling
// pattern goes through the chosen inverse transform to a direction; each light carries an equal
// share of the map's luminance power, luminanceSr / N, coloured by the map at the sample (the
// blended colour of havran_sampler.h for the Havran sampler, the pixel's colour for the standard
// one), so the rgb of all N lights sum to the map's integral of radiance over solid angle (to
// sampling accuracy). Light i comes from pattern point i and is listed i-th: the first k lights of
// an N-light set are exactly the k-light set.
#pragma once

#include <span>

#include <glm/vec2.hpp>

#include "core/env_map.h"
#include "core/light.h"
#include "core/sampling_tables.h"

namespace vem {

enum class SamplerKind { Havran, Standard };

[[nodiscard]] const char* samplerName(SamplerKind kind);

// `pattern` holds the pattern points to use (a prefix of defaultSamplingPattern(), one per light).
// `tables` must have been built from `map`.
[[nodiscard]] LightSet generateLights(const EnvMap& map, const SamplingTables& tables,
                                      std::span<const glm::dvec2> pattern, SamplerKind kind);

}  // namespace vem
