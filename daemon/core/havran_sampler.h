// Havran's inverse transform (paper 004 section 3.1, after Havran, Dmitriev and Seidel 2003):
// unit square -> cylinder coordinates (s, w) by an equal-area map (the concentric map to the disk for
// the hemisphere, as in the paper: s = rho^2, w = psi_d / 2 pi; Clarberg's equal-area octahedral map
// for the full sphere; surface_parameterization.h), a warp of s and w by 1D cumulative tables, and
// the equal-area map back to the surface.
//
// The warp: s is inverted through the tent marginal over the row coordinate r
// (SamplingTables::tentCdf, the row masses interpolated linearly between row centres); w is
// inverted through the conditional over columns at r, which is the linear interpolation of the two
// neighbouring rows' cumulative masses (weights (1 - t) and t, each row weighted by its pixel solid
// angle). So the density sampled is the map's importance interpolated linearly in r between row
// centres and constant within a column: a continuous density, strictly positive thanks to the floor
// (sampling_tables.h), which makes the mapping continuous and bijective for any non-negative map,
// across the concentric map's diagonals, at the pole, across the psi = 0 seam (the conditional
// tables wrap) and across the octahedral map's equator.
// Surface from (r, xc): s is linear in r within a row; cos theta = 1 - s (hemisphere) or 1 - 2 s
// (sphere); the map's azimuth follows xc (env_map.h).
#pragma once

#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/sampling_tables.h"

namespace vem {

// Where a square point lands: its unit direction and its map coordinates (row r, column xc).
struct MapSample {
  glm::dvec3 dir{0.0, 1.0, 0.0};
  double r = 0.0;
  double xc = 0.0;
};

[[nodiscard]] MapSample havranSample(const SamplingTables& tables, glm::dvec2 square);
// For each s of `sAscending` (fractions of the mass in [0, 1], ascending), the row coordinate r in
// [0, H] where the tent marginal reaches it: where havranSample takes square points whose cylinder
// coordinate is s. One pass up the marginal; `rows` has the size of `sAscending`.
void havranRowCoords(const SamplingTables& tables, std::span<const double> sAscending,
                     std::span<double> rows);
// Inverse: the square point that lands on `dir` (dir in the map's domain).
[[nodiscard]] glm::dvec2 havranSquare(const SamplingTables& tables, glm::dvec3 dir);
// Density of havranSample's directions per steradian (0 outside the map's domain).
[[nodiscard]] double havranPdfSr(const SamplingTables& tables, glm::dvec3 dir);

// The rows whose interpolation holds at row coordinate r: rows y0 and y1 with weight t on y1.
struct RowBlend {
  int y0 = 0;
  int y1 = 0;
  double t = 0.0;
};
[[nodiscard]] RowBlend rowBlendAt(const SamplingTables& tables, double r);

}  // namespace vem
