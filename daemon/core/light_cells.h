// LightCells: which part of the map each light stands for (issue 19, part 3).
//
// Both samplers map a point (a, b) of the unit square "warp domain" to the map so that the map's
// importance (luminance x solid angle, floor included; sampling_tables.h) is uniform over it: a is
// the fraction of the importance in the rows above the point (the marginal), b the fraction of its
// row's importance to the left of it (the conditional). So any region of the warp domain holds the
// share of the map's importance equal to its area.
//
// The cells cut the warp domain into N rectangles of area exactly 1 / N, one per pattern point,
// each holding its own point: a k-d split that cuts a rectangle holding n points across its longer
// side into two holding m and n - m points, with areas m / n and (n - m) / n of it. The cut line is
// then fixed by m; of the m near n / 2, the one nearest whose line passes between the m-th and the
// (m + 1)-th point along that side is taken, so no point ends on the wrong side (when no such m
// exists, n / 2 is taken and a point may lie outside its cell; measured in
// tests/core/light_colour_test.cpp). Every cell therefore holds the same importance as every light
// carries, and the cells tile the domain, so the colours integrated over them sum, per channel, to
// the map's integral (light_generator.h). The cells depend on the pattern prefix only, not on the
// map: they are built once per light count.
//
// What "the part of the map it stands for" means at high contrast: in a row that holds a sun, the
// sky to its left and right is a thin sliver of the warp domain, so a light that lands there has a
// cell that reaches into the sun and takes its colour: the light carries the sun's energy, 1 / N of
// the map, from a direction where the sky alone has less than that.
//
// Warp domain of each sampler: the standard sampler's is its unit square itself; the Havran
// sampler's is the cylinder (s, w) its equal-area map reaches (surface_parameterization.h), which
// its tables then warp (havran_sampler.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/sampling_tables.h"

namespace vem {

struct LightCell {
  double a0 = 0.0;  // the rectangle [a0, a1] x [b0, b1] of the warp domain
  double a1 = 0.0;
  double b0 = 0.0;
  double b1 = 0.0;
  std::uint32_t light = 0;  // the pattern index of its light
  std::uint32_t a0Edge = 0;  // a0 = LightCells::aEdges[a0Edge], and a1 likewise
  std::uint32_t a1Edge = 0;
};

struct LightCells {
  std::size_t count = 0;  // N: the number of lights, and of cells
  std::vector<LightCell> cells;  // in k-d order
  // The cells' edges across a, each once, ascending: what the sampler maps to rows once per frame.
  std::vector<double> aEdges;
};

// The cells of `warpPoints` (point i in the warp domain, i < N). Points outside [0, 1]^2 are
// clamped into it.
[[nodiscard]] LightCells buildLightCells(std::span<const glm::dvec2> warpPoints);

// How a sampler spreads each row's importance over the row coordinate r: the standard sampler's
// box marginal keeps row y on [y, y + 1]; the Havran sampler's tent marginal interpolates the rows
// linearly between their centres, so row y weighs in from y - 0.5 to y + 1.5.
enum class RowWeighting { Box, Tent };

// The map's rgb over each cell (map units x sr, floor included as grey), indexed by light. Cell k
// (cells.cells[k]) covers the rows rowRanges[k] = (r0, r1), the row coordinates its sampler maps
// its range of a to; each row y enters with its weight over [r0, r1] under `rows`, and within the
// row, each (row, 16-pixel block) box of `tables` with the fraction of its range of b (the row's
// own conditional) inside the cell's. The cells' rows tile [0, H] and each row's weights sum to 1
// over them; their ranges of b tile each row's. So per channel the cells sum to the map's integral
// plus the floor's, and each cell's luminance is exactly tables.totalMass / N (a cell's b-range
// holds that fraction of every row's importance). `tables` must be non-black.
[[nodiscard]] std::vector<glm::dvec3> cellRadianceSr(const SamplingTables& tables,
                                                     const LightCells& cells,
                                                     std::span<const glm::dvec2> rowRanges,
                                                     RowWeighting rows);

}  // namespace vem
