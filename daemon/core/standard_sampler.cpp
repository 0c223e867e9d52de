#include "core/standard_sampler.h"

#include <algorithm>
#include <cmath>

namespace vem {
namespace {

// Column coordinate in row y where the row's cumulative reaches fraction v of its total.
double invertRow(const SamplingTables& t, int y, double v) {
  const double target = v * t.rowCumulativeAt(y, t.width);
  int lo = 0;
  int hi = t.width;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (t.rowCumulativeAt(y, mid) <= target) lo = mid; else hi = mid;
  }
  const double c0 = t.rowCumulativeAt(y, lo);
  const double c1 = t.rowCumulativeAt(y, lo + 1);
  return lo + std::clamp((target - c0) / (c1 - c0), 0.0, 1.0);
}

}  // namespace

MapSample standardSample(const SamplingTables& t, glm::dvec2 square) {
  const double target = square.x * t.totalMass;
  const auto it = std::upper_bound(t.boxCdf.begin() + 1, t.boxCdf.end() - 1, target);
  const int y = int(it - t.boxCdf.begin()) - 1;
  const double within = (target - t.boxCdf[std::size_t(y)]) / t.rowMass[std::size_t(y)];
  const double r = y + std::clamp(within, 0.0, 1.0);
  double xc = invertRow(t, y, square.y);
  if (xc >= t.width) xc -= t.width;
  return {directionFromMapCoords(t, r, xc), r, xc};
}

glm::dvec2 standardSquare(const SamplingTables& t, glm::dvec3 dir) {
  const MapCoords c = mapCoordsFromDirection(t, dir);
  const int y = std::clamp(int(c.r), 0, t.height - 1);
  const double u = (t.boxCdf[std::size_t(y)] + (c.r - y) * t.rowMass[std::size_t(y)]) / t.totalMass;
  const double v = t.rowCumulativeAt(y, c.xc) / t.rowCumulativeAt(y, t.width);
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
