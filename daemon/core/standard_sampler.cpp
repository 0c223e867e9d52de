#include "core/standard_sampler.h"

#include <algorithm>
#include <cmath>

namespace vem {
namespace {

// Column coordinate in row y where the row's cumulative reaches fraction v of its total.
double invertRow(const SamplingTables& t, int y, double v) {
  const RowPair row{y, 1.0, y, 0.0};
  return invertBlendedCumulative(t, row, v * blendedCumulative(t, row, t.width));
}

}  // namespace

namespace {

// The row coordinate of `target` in [0, totalMass] in row y, the row whose mass holds it.
double rowCoordIn(const SamplingTables& t, std::size_t y, double target) {
  const double within = (target - t.boxCdf[y]) / t.rowMass[y];
  return double(y) + std::clamp(within, 0.0, 1.0);
}

double standardRowCoord(const SamplingTables& t, double u) {
  const double target = std::clamp(u, 0.0, 1.0) * t.totalMass;
  const auto it = std::upper_bound(t.boxCdf.begin() + 1, t.boxCdf.end() - 1, target);
  return rowCoordIn(t, std::size_t(it - t.boxCdf.begin()) - 1, target);
}

}  // namespace

void standardRowCoords(const SamplingTables& t, std::span<const double> uAscending,
                       std::span<double> rows) {
  std::size_t y = 0;  // targets ascend, so the row only moves down
  for (std::size_t i = 0; i < uAscending.size(); ++i) {
    const double target = std::clamp(uAscending[i], 0.0, 1.0) * t.totalMass;
    while (y + 2 < t.boxCdf.size() && t.boxCdf[y + 1] <= target) ++y;
    rows[i] = rowCoordIn(t, y, target);
  }
}

MapSample standardSample(const SamplingTables& t, glm::dvec2 square) {
  const double r = standardRowCoord(t, square.x);
  const int y = std::min(int(r), t.height - 1);
  double xc = invertRow(t, y, square.y);
  if (xc >= t.width) xc -= t.width;
  return {directionFromMapCoords(t, r, xc), r, xc};
}

glm::dvec2 standardSquare(const SamplingTables& t, glm::dvec3 dir) {
  const MapCoords c = mapCoordsFromDirection(t, dir);
  const int y = std::clamp(int(c.r), 0, t.height - 1);
  const double u = (t.boxCdf[std::size_t(y)] + (c.r - y) * t.rowMass[std::size_t(y)]) / t.totalMass;
  const RowPair row{y, 1.0, y, 0.0};
  const double v = blendedCumulative(t, row, c.xc) / blendedCumulative(t, row, t.width);
  return {u, v};
}

double standardPdfSr(const SamplingTables& t, glm::dvec3 dir) {
  if (t.layout == MapLayout::Hemisphere && dir.y < 0) return 0.0;
  const MapCoords c = mapCoordsFromDirection(t, dir);
  const int y = std::clamp(int(c.r), 0, t.height - 1);
  const int x = std::clamp(int(c.xc), 0, t.width - 1);
  // Proportional to the pixel's luminance (floor included): importance over solid angle.
  return t.pixelY(y, x) / t.totalMass;
}

}  // namespace vem
