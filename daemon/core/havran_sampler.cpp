#include "core/havran_sampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/surface_parameterization.h"

namespace vem {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Row coordinate r where the tent marginal's cumulative reaches `target` in [0, totalMass], given
// the segment [knot j, knot j + 1] of tentCdf that holds it.
double invertTentMarginalIn(const SamplingTables& t, std::size_t j, double target) {
  const auto& cdf = t.tentCdf;
  const double delta = std::max(0.0, target - cdf[j]);
  const int h = t.height;
  if (j == 0) return std::min(0.5, delta / t.rowMass[0]);
  if (j == std::size_t(h))
    return std::min(double(h), h - 0.5 + delta / t.rowMass[std::size_t(h) - 1]);
  // Density rises linearly from a = rowMass[j-1] to b = rowMass[j] over one unit of r:
  // a x + (b - a) x^2 / 2 = delta, solved in the form that stays exact when a ~ b.
  const double a = t.rowMass[j - 1];
  const double b = t.rowMass[j];
  const double x = 2 * delta / (a + std::sqrt(std::max(0.0, a * a + 2 * (b - a) * delta)));
  return j - 0.5 + std::clamp(x, 0.0, 1.0);
}

double invertTentMarginal(const SamplingTables& t, double target) {
  const auto& cdf = t.tentCdf;
  const auto it = std::upper_bound(cdf.begin() + 1, cdf.end() - 1, target);
  return invertTentMarginalIn(t, std::size_t(it - cdf.begin()) - 1, target);
}

// Cumulative of the tent marginal at row coordinate r.
double tentMarginalAt(const SamplingTables& t, double r) {
  const int h = t.height;
  if (r <= 0.5) return std::max(0.0, r) * t.rowMass[0];
  if (r >= h - 0.5)
    return t.tentCdf[std::size_t(h)] +
           (std::min(r, double(h)) - (h - 0.5)) * t.rowMass[std::size_t(h) - 1];
  const std::size_t j = std::size_t(r + 0.5);  // r in [j - 0.5, j + 0.5)
  const double x = r - (j - 0.5);
  const double a = t.rowMass[j - 1];
  const double b = t.rowMass[j];
  return t.tentCdf[j] + a * x + 0.5 * (b - a) * x * x;
}

// The two rows whose cumulative masses blend at row coordinate r: weights (1 - t) and t, each
// times its row's pixel solid angle.
RowPair rowPairAt(const SamplingTables& t, double r) {
  const RowBlend rows = rowBlendAt(t, r);
  return {rows.y0, (1 - rows.t) * t.pixelSolidAngleSr[std::size_t(rows.y0)], rows.y1,
          rows.t * t.pixelSolidAngleSr[std::size_t(rows.y1)]};
}

}  // namespace

RowBlend rowBlendAt(const SamplingTables& t, double r) {
  if (r <= 0.5) return {0, 0, 0.0};
  if (r >= t.height - 0.5) return {t.height - 1, t.height - 1, 0.0};
  const int y0 = int(r - 0.5);
  return {y0, y0 + 1, r - 0.5 - y0};
}

void havranRowCoords(const SamplingTables& t, std::span<const double> sAscending,
                     std::span<double> rows) {
  const auto& cdf = t.tentCdf;
  std::size_t j = 0;  // the segment holding the target: targets ascend, so it only moves up
  for (std::size_t i = 0; i < sAscending.size(); ++i) {
    const double target = std::clamp(sAscending[i], 0.0, 1.0) * t.totalMass;
    while (j + 2 < cdf.size() && cdf[j + 1] <= target) ++j;
    rows[i] = invertTentMarginalIn(t, j, target);
  }
}

MapSample havranSample(const SamplingTables& t, glm::dvec2 square) {
  const CylinderPoint cylinder = cylinderFromSquare(t.layout, square);
  const double r = invertTentMarginal(t, cylinder.s * t.totalMass);
  const RowPair rows = rowPairAt(t, r);
  double xc = invertBlendedCumulative(t, rows, cylinder.w * blendedCumulative(t, rows, t.width));
  if (xc >= t.width) xc -= t.width;
  return {directionFromMapCoords(t, r, xc), r, xc};
}

glm::dvec2 havranSquare(const SamplingTables& t, glm::dvec3 dir) {
  const MapCoords c = mapCoordsFromDirection(t, dir);
  const double u = tentMarginalAt(t, c.r) / t.totalMass;
  const RowPair rows = rowPairAt(t, c.r);
  double w = blendedCumulative(t, rows, c.xc) / blendedCumulative(t, rows, t.width);
  if (w >= 1) w -= 1;
  return squareFromCylinder(t.layout, {std::clamp(u, 0.0, 1.0), w});
}

double havranPdfSr(const SamplingTables& t, glm::dvec3 dir) {
  if (t.layout == MapLayout::Hemisphere && dir.y < 0) return 0.0;
  const MapCoords c = mapCoordsFromDirection(t, dir);
  const RowPair rows = rowPairAt(t, c.r);
  const int x = std::clamp(int(c.xc), 0, t.width - 1);
  // Joint density per unit r and unit psi: the blended mass of column x over its width 2 pi / W.
  const double massPerColumn =
      rows.weight0 * t.pixelY(rows.row0, x) + rows.weight1 * t.pixelY(rows.row1, x);
  const double densityRPsi = massPerColumn / t.totalMass * t.width / kTwoPi;
  // d(omega) = (1 - cos theta_max) ds d(psi), and ds = (s_{y+1} - s_y) dr within row y.
  const int y = std::clamp(int(c.r), 0, t.height - 1);
  const double oneMinusCosMax = t.layout == MapLayout::Sphere ? 2.0 : 1.0;
  const double dsDr = t.sEdges[std::size_t(y) + 1] - t.sEdges[std::size_t(y)];
  return densityRPsi / (oneMinusCosMax * dsDr);
}

}  // namespace vem
