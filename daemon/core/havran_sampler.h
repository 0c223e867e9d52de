// Havran's inverse transform (paper 004 section 3.1, after Havran, Dmitriev and Seidel 2003):
// unit square -> unit disk by the concentric map, a warp of the disk by 1D cumulative tables over
// its radius and its angle, and the equal-area map from the disk to the hemisphere (or sphere).
//
// The warp: the disk radius rho gives u = rho^2 (uniform in area); u is inverted through the tent
// marginal over the row coordinate r (SamplingTables::tentCdf, the row masses interpolated linearly
// between row centres); the disk angle psi_d / 2 pi is inverted through the conditional over
// columns at r, which is the linear interpolation of the two neighbouring rows' cumulative masses
// (weights (1 - t) and t, each row weighted by its pixel solid angle). So the density sampled is
// the map's importance interpolated linearly in r between row centres and constant within a column:
// a continuous density, strictly positive thanks to the floor (sampling_tables.h), which makes the
// mapping continuous and bijective for any non-negative map, across the concentric map's diagonals,
// at the pole and across the psi = 0 seam (the conditional tables wrap).
// Equal-area disk to surface: s = u-shaped area coordinate; cos theta = 1 - s (hemisphere) or
// 1 - 2 s (sphere), so the disk's rim is the horizon (hemisphere) or the nadir (sphere).
#pragma once

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

// The interpolated (rgb, luminance) mass density of the map at (r, xc), floor included: what the
// Havran sampler's density is proportional to, and the colour a light sampled there carries.
struct BlendedPixel {
  glm::dvec3 rgb{0.0};
  double luminance = 0.0;
};
[[nodiscard]] BlendedPixel blendedPixelAt(const EnvMap& map, const SamplingTables& tables, double r,
                                          double xc);

}  // namespace vem
