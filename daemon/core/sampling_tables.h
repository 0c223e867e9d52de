// SamplingTables: the per-frame importance of an environment map and the cumulative tables both
// samplers invert (paper 004 section 3.1).
//
// Importance of a pixel = its Rec. 709 luminance times its solid angle (color.h, env_map.h).
// A pixel with a NaN, infinite or negative channel counts as black (and is counted here so the
// shell can warn once). A grey floor of kFloorFraction times the map's mean luminance is added to
// every pixel's importance (and, as grey, to its colour) so that the cumulative tables are strictly
// increasing for any non-negative map: this is what makes the Havran mapping continuous and
// bijective everywhere, also across black regions. Its effect on the lights' totals is
// kFloorFraction, relative. An all-black map (no positive luminance anywhere) gets a uniform
// importance instead, so the lights keep well-defined directions; `black` is set and the light
// generator then emits rgb exactly 0.
//
// Coordinates: row coordinate r in [0, H] (row y spans [y, y + 1]) and column coordinate xc in
// [0, W] (env_map.h). Within row y the area coordinate s = (1 - cos theta) / (1 - cos theta_max) is
// linear in r; s is uniform in solid angle: d(omega) = (1 - cos theta_max) ds d(psi).
// Sums are accumulated and stored in double: a 4096 x 2048 map with a 1e8 sun over a 1e-3 sky needs
// it (float would lose the sky under the sun in the cumulative sums).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "core/env_map.h"

namespace vem {

inline constexpr double kFloorFraction = 1e-6;

// Columns are summed in blocks of kColumnBlock: the per-pixel luminances are kept in float (the
// pixel values themselves) and the sums at block edges in double, which halves the memory a frame
// writes compared with a double cumulative per pixel, at the same precision.
inline constexpr int kColumnBlock = 16;

struct SamplingTables {
  MapLayout layout = MapLayout::Sphere;
  int width = 0;
  int height = 0;
  int blocksPerRow = 0;               // ceil(width / kColumnBlock)
  std::vector<float> pixelLuminance;  // per pixel, sanitised, no floor; row-major
  // Per row y, the luminance and the rgb summed over columns [0, kColumnBlock b) in double
  // (sanitised, the floor included, as grey in the rgb), side by side at
  // 4 (y * (blocksPerRow + 1) + b) + {0: luminance, 1-3: r, g, b}, b = blocksPerRow being the whole
  // row: the samplers' importance at block edges, and the colour the lights' cells integrate
  // (light_cells.h), one edge's sums in one cache line.
  std::vector<double> blockCumulativeYRgb;
  std::vector<double> pixelSolidAngleSr;  // per row
  std::vector<double> sEdges;             // height + 1 area coordinates of the row edges
  std::vector<double> rowMass;            // per row: solid angle x (luminance sum + width x floor)
  // Marginal over rows for the standard sampler: cumulative rowMass at the row edges (height + 1).
  std::vector<double> boxCdf;
  // Marginal for the Havran sampler: rowMass interpolated linearly in r between row centres
  // (constant in the outer half rows), cumulative at knots r = 0, 0.5, 1.5, ..., H - 0.5, H.
  std::vector<double> tentCdf;
  double floorY = 0.0;        // luminance added to every pixel
  double totalMass = 0.0;     // sum of rowMass = boxCdf.back() = tentCdf.back()
  double luminanceSr = 0.0;   // integral of the (sanitised) luminance over solid angle, no floor
  std::size_t badPixels = 0;  // pixels with a NaN, infinite or negative channel (counted as black)
  bool black = false;

  // Luminance of column x in row y, floor included.
  [[nodiscard]] double pixelY(int y, int x) const {
    return double(pixelLuminance[std::size_t(y) * std::size_t(width) + std::size_t(x)]) + floorY;
  }
  // The importance of row y over its first `block` blocks: luminance, floor included, no solid
  // angle.
  [[nodiscard]] double massAtBlock(int y, int block) const {
    return blockCumulativeYRgb[4 * (std::size_t(y) * std::size_t(blocksPerRow + 1) +
                                    std::size_t(block))];
  }
  // Luminance of row y summed over columns [0, x), no floor (O(kColumnBlock)).
  [[nodiscard]] double cumulativeY(int y, int x) const;
};

// Two rows blended with weights (per unit luminance, floor included): the Havran sampler's
// conditional over columns between row centres, or one row alone (weight1 = 0) for the standard
// one.
struct RowPair {
  int row0 = 0;
  double weight0 = 1.0;
  int row1 = 0;
  double weight1 = 0.0;
};

// The blended cumulative over columns [0, xc), xc in [0, W], linear within a pixel.
[[nodiscard]] double blendedCumulative(const SamplingTables& tables, const RowPair& rows,
                                       double xc);
// Its inverse: the column coordinate xc in [0, W] where it reaches `target` (clamped to the range).
[[nodiscard]] double invertBlendedCumulative(const SamplingTables& tables, const RowPair& rows,
                                             double target);

// Builds the tables for `map`. `recycled` lends its storage (pass last frame's tables to avoid
// allocating every frame); its contents are ignored.
[[nodiscard]] SamplingTables buildSamplingTables(const EnvMap& map, SamplingTables recycled = {});

// The integral of the map's (sanitised) rgb over solid angle, per channel (map units x sr): what
// the lights' rgb sum to (to the floor's share, kFloorFraction). A check for tests and tools; the
// lights themselves integrate SamplingTables::blockCumulativeYRgb over their cells.
[[nodiscard]] glm::dvec3 radianceIntegralSr(const EnvMap& map);

// A pixel's rgb, or 0 when a channel is NaN, infinite or negative.
[[nodiscard]] glm::dvec3 sanitizedRgb(const EnvMap& map, int x, int y);

// The row coordinate r in [0, H] of polar angle theta.
[[nodiscard]] double rowCoordFromTheta(const SamplingTables& tables, double thetaRad);
// The area coordinate s of row coordinate r, and the unit direction of (r, xc).
[[nodiscard]] double sFromRowCoord(const SamplingTables& tables, double r);
[[nodiscard]] glm::dvec3 directionFromMapCoords(const SamplingTables& tables, double r, double xc);
// The map coordinates (r, xc) of a unit direction (inverse of directionFromMapCoords).
struct MapCoords {
  double r = 0.0;
  double xc = 0.0;
};
[[nodiscard]] MapCoords mapCoordsFromDirection(const SamplingTables& tables, glm::dvec3 dir);

}  // namespace vem
