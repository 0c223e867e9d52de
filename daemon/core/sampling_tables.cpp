#include "core/sampling_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/color.h"

namespace vem {
namespace {

// A channel value as the importance sees it: NaN, +-Inf and negatives become 0.
inline float cleanChannel(float v) {
  return (v >= 0.0F && v <= std::numeric_limits<float>::max()) ? v : 0.0F;
}

void resizeFor(SamplingTables& t, const EnvMap& map) {
  t.layout = map.layout;
  t.width = map.width;
  t.height = map.height;
  t.rowCumulativeY.resize(std::size_t(map.height) * std::size_t(map.width + 1));
  t.pixelSolidAngleSr.resize(std::size_t(map.height));
  t.sEdges.resize(std::size_t(map.height) + 1);
  t.rowMass.resize(std::size_t(map.height));
  t.boxCdf.resize(std::size_t(map.height) + 1);
  t.tentCdf.resize(std::size_t(map.height) + 2);
}

// One row: cumulative luminance, and the row's rgb sum. Returns the number of bad pixels.
std::size_t accumulateRow(const float* rgb, int width, double* cumulative, glm::dvec3& rowRgb) {
  std::size_t bad = 0;
  double sum = 0;
  glm::dvec3 rgbSum(0);
  cumulative[0] = 0;
  for (int x = 0; x < width; ++x) {
    const float r = rgb[3 * x], g = rgb[3 * x + 1], b = rgb[3 * x + 2];
    const float cr = cleanChannel(r), cg = cleanChannel(g), cb = cleanChannel(b);
    bad += (cr != r || cg != g || cb != b) ? 1 : 0;
    sum += luminance(double(cr), double(cg), double(cb));
    cumulative[x + 1] = sum;
    rgbSum += glm::dvec3(cr, cg, cb);
  }
  rowRgb = rgbSum;
  return bad;
}

void buildMarginals(SamplingTables& t) {
  const int h = t.height;
  t.boxCdf[0] = 0;
  for (int y = 0; y < h; ++y) {
    t.rowMass[std::size_t(y)] =
        t.pixelSolidAngleSr[std::size_t(y)] * (t.cumulativeY(y, t.width) + t.width * t.floorY);
    t.boxCdf[std::size_t(y) + 1] = t.boxCdf[std::size_t(y)] + t.rowMass[std::size_t(y)];
  }
  // Tent marginal: half a row of constant density at each end, trapezoids between row centres.
  t.tentCdf[0] = 0;
  t.tentCdf[1] = 0.5 * t.rowMass[0];
  for (int j = 1; j < h; ++j) {
    t.tentCdf[std::size_t(j) + 1] =
        t.tentCdf[std::size_t(j)] + 0.5 * (t.rowMass[std::size_t(j) - 1] + t.rowMass[std::size_t(j)]);
  }
  t.tentCdf[std::size_t(h) + 1] = t.tentCdf[std::size_t(h)] + 0.5 * t.rowMass[std::size_t(h) - 1];
  t.totalMass = t.boxCdf[std::size_t(h)];
}

}  // namespace

SamplingTables buildSamplingTables(const EnvMap& map, SamplingTables recycled) {
  SamplingTables t = std::move(recycled);
  resizeFor(t, map);
  const double oneMinusCosMax = map.layout == MapLayout::Sphere ? 2.0 : 1.0;
  t.badPixels = 0;
  t.luminanceSr = 0;
  t.rgbSr = glm::dvec3(0);
  for (int y = 0; y <= map.height; ++y) {
    const double theta = thetaFromRowCoord(map.layout, map.height, y);
    const double half = std::sin(0.5 * theta);
    t.sEdges[std::size_t(y)] = 2 * half * half / oneMinusCosMax;  // 1 - cos = 2 sin^2(theta / 2)
  }
  for (int y = 0; y < map.height; ++y) {
    const double omega = pixelSolidAngleSr(map.layout, map.width, map.height, y);
    t.pixelSolidAngleSr[std::size_t(y)] = omega;
    glm::dvec3 rowRgb;
    double* cumulative = &t.rowCumulativeY[std::size_t(y) * std::size_t(map.width + 1)];
    t.badPixels += accumulateRow(&map.rgb[3 * std::size_t(y) * std::size_t(map.width)], map.width,
                                 cumulative, rowRgb);
    t.luminanceSr += omega * cumulative[map.width];
    t.rgbSr += omega * rowRgb;
  }
  t.black = !(t.luminanceSr > 0);
  // Uniform importance for a black map; otherwise a floor far below anything that matters.
  t.floorY = t.black ? 1.0 : kFloorFraction * t.luminanceSr / coveredSolidAngleSr(map.layout);
  buildMarginals(t);
  return t;
}

double SamplingTables::rowCumulativeAt(int y, double xc) const {
  const int x = std::clamp(int(xc), 0, width - 1);
  const double lo = cumulativeY(y, x) + x * floorY;
  const double hi = cumulativeY(y, x + 1) + (x + 1) * floorY;
  return lo + (xc - x) * (hi - lo);
}

glm::dvec3 sanitizedRgb(const EnvMap& map, int x, int y) {
  const glm::vec3 v = map.at(x, y);
  return {cleanChannel(v.x), cleanChannel(v.y), cleanChannel(v.z)};
}

double rowCoordFromTheta(const SamplingTables& t, double thetaRad) {
  const double rowHeight = thetaMaxRad(t.layout) / t.height;
  const int y = std::clamp(int(thetaRad / rowHeight), 0, t.height - 1);
  const double oneMinusCosMax = t.layout == MapLayout::Sphere ? 2.0 : 1.0;
  const double half = std::sin(0.5 * thetaRad);
  const double s = 2 * half * half / oneMinusCosMax;
  const double s0 = t.sEdges[std::size_t(y)];
  const double s1 = t.sEdges[std::size_t(y) + 1];
  return y + std::clamp((s - s0) / (s1 - s0), 0.0, 1.0);
}

double sFromRowCoord(const SamplingTables& t, double r) {
  const int y = std::clamp(int(r), 0, t.height - 1);
  const double s0 = t.sEdges[std::size_t(y)];
  const double s1 = t.sEdges[std::size_t(y) + 1];
  return s0 + (r - y) * (s1 - s0);
}

glm::dvec3 directionFromMapCoords(const SamplingTables& t, double r, double xc) {
  const double s = std::clamp(sFromRowCoord(t, r), 0.0, 1.0);
  // Hemisphere: cos = 1 - s, sin = sqrt(s (2 - s)); sphere: cos = 1 - 2 s, sin = 2 sqrt(s (1 - s)).
  const bool sphere = t.layout == MapLayout::Sphere;
  const double cosTheta = sphere ? 1 - 2 * s : 1 - s;
  const double sinTheta = sphere ? 2 * std::sqrt(s * (1 - s)) : std::sqrt(s * (2 - s));
  const double phi = phiFromColumnCoord(t.layout, t.width, xc);
  return {sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)};
}

MapCoords mapCoordsFromDirection(const SamplingTables& t, glm::dvec3 dir) {
  const double theta = std::atan2(std::hypot(dir.x, dir.z), dir.y);
  double psi = std::atan2(dir.z, dir.x);  // phi in (-pi, pi]
  if (t.layout == MapLayout::Sphere) psi += std::numbers::pi;
  if (psi < 0) psi += 2 * std::numbers::pi;
  double xc = psi / (2 * std::numbers::pi) * t.width;
  if (xc >= t.width) xc -= t.width;
  return {rowCoordFromTheta(t, theta), xc};
}

}  // namespace vem
