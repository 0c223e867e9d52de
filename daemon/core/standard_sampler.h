// The standard inverse transform (paper 004 section 3.1, as in [PH04, Bur04]): the baseline the
// Havran sampler is compared against, fed by the same pattern and the same SamplingTables.
// The square's u selects a row through the marginal over rows (piecewise constant per row,
// SamplingTables::boxCdf), v selects a column within that row through its own conditional; the
// density is exactly proportional to the map's importance (floor included), but the mapping jumps
// wherever u crosses a row boundary.
#pragma once

#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/havran_sampler.h"
#include "core/sampling_tables.h"

namespace vem {

[[nodiscard]] MapSample standardSample(const SamplingTables& tables, glm::dvec2 square);
// For each u of `uAscending` (fractions of the mass in [0, 1], ascending), the row coordinate r in
// [0, H] where the box marginal reaches it: where standardSample takes square points (u, v). One
// pass down the marginal; `rows` has the size of `uAscending`.
void standardRowCoords(const SamplingTables& tables, std::span<const double> uAscending,
                       std::span<double> rows);
[[nodiscard]] glm::dvec2 standardSquare(const SamplingTables& tables, glm::dvec3 dir);
[[nodiscard]] double standardPdfSr(const SamplingTables& tables, glm::dvec3 dir);

}  // namespace vem
