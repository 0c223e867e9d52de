// From an environment map to N directional lights (paper 004 section 3): each point of the sampling
// pattern goes through the chosen inverse transform to a direction; each light carries an equal
// share of the map's luminance power, luminanceSr / N, with the colour of the part of the map it
// stands for: its cell (light_cells.h), the 1/N of the map's importance nearest to its pattern
// point in the sampler's warp domain. So, per channel, the N lights' rgb sum to the map's integral
// of radiance over solid angle (to the floor's share, kFloorFraction, sampling_tables.h), at any N,
// and a light's colour is an average over its cell, not one pixel's.
// Light i comes from pattern point i and is listed i-th: the first k lights of an N-light set have
// exactly the directions and identities of the k-light set (the progressive property); their
// colours are those of their (smaller) cells in the N-light set.
#pragma once

#include <span>

#include <glm/vec2.hpp>

#include "core/env_map.h"
#include "core/light.h"
#include "core/light_cells.h"
#include "core/sampling_tables.h"

namespace vem {

enum class SamplerKind { Havran, Standard };

[[nodiscard]] const char* samplerName(SamplerKind kind);

// The cells of the first pattern.size() pattern points under `kind` on `layout`: built once per
// light count and reused for every frame (they do not depend on the map).
[[nodiscard]] LightCells lightCellsFor(MapLayout layout, std::span<const glm::dvec2> pattern,
                                       SamplerKind kind);

// `pattern` holds the pattern points to use (a prefix of defaultSamplingPattern(), one per light),
// `cells` = lightCellsFor(tables.layout, pattern, kind).
[[nodiscard]] LightSet generateLights(const SamplingTables& tables,
                                      std::span<const glm::dvec2> pattern, SamplerKind kind,
                                      const LightCells& cells);
// The same, building the cells on the way (about N log N; callers that sample every frame keep
// the cells instead).
[[nodiscard]] LightSet generateLights(const SamplingTables& tables,
                                      std::span<const glm::dvec2> pattern, SamplerKind kind);

}  // namespace vem
