#include "core/sampling_tables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/color.h"

namespace vem {
namespace {

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

// A pixel's luminance, or 0 when it is bad: a NaN, infinite or negative channel makes its luminance
// NaN or infinite, or its smallest channel negative. Branch-free.
inline float pixelLuminance(const float* rgb, unsigned& bad) {
  const float r = rgb[0], g = rgb[1], b = rgb[2];
  const float y = float(kRec709R) * r + float(kRec709G) * g + float(kRec709B) * b;
  const bool good = std::min(std::min(r, g), b) >= 0.0F && y <= std::numeric_limits<float>::max();
  bad += unsigned(!good);
  return good ? y : 0.0F;
}

// One row in one pass: cumulative[x] = luminance summed over columns [0, x). The sums run in double
// in blocks of four pixels, so the serial dependency is one addition per block, not per pixel.
// Returns the number of bad pixels.
std::size_t accumulateRow(const float* rgb, int width, double* cumulative) {
  unsigned bad = 0;
  double base = 0;
  cumulative[0] = 0;
  int x = 0;
  for (; x + 4 <= width; x += 4) {
    const double a = pixelLuminance(rgb + 3 * x, bad);
    const double b = a + double(pixelLuminance(rgb + 3 * x + 3, bad));
    const double c = b + double(pixelLuminance(rgb + 3 * x + 6, bad));
    const double d = c + double(pixelLuminance(rgb + 3 * x + 9, bad));
    cumulative[x + 1] = base + a;
    cumulative[x + 2] = base + b;
    cumulative[x + 3] = base + c;
    cumulative[x + 4] = base + d;
    base += d;
  }
  for (; x < width; ++x) {
    base += double(pixelLuminance(rgb + 3 * x, bad));
    cumulative[x + 1] = base;
  }
  return bad;
}

// A pixel as the importance sees it: any NaN, infinite or negative channel makes it black.
inline bool goodPixel(glm::vec3 v) {
  const float rgb[3] = {v.x, v.y, v.z};
  unsigned bad = 0;
  (void)pixelLuminance(rgb, bad);
  return bad == 0;
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
  for (int y = 0; y <= map.height; ++y) {
    const double theta = thetaFromRowCoord(map.layout, map.height, y);
    const double half = std::sin(0.5 * theta);
    t.sEdges[std::size_t(y)] = 2 * half * half / oneMinusCosMax;  // 1 - cos = 2 sin^2(theta / 2)
  }
  for (int y = 0; y < map.height; ++y) {
    const double omega = pixelSolidAngleSr(map.layout, map.width, map.height, y);
    t.pixelSolidAngleSr[std::size_t(y)] = omega;
    double* cumulative = &t.rowCumulativeY[std::size_t(y) * std::size_t(map.width + 1)];
    t.badPixels +=
        accumulateRow(&map.rgb[3 * std::size_t(y) * std::size_t(map.width)], map.width, cumulative);
    t.luminanceSr += omega * cumulative[map.width];
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

glm::dvec3 radianceIntegralSr(const EnvMap& map) {
  glm::dvec3 total(0);
  for (int y = 0; y < map.height; ++y) {
    glm::dvec3 row(0);
    for (int x = 0; x < map.width; ++x) row += sanitizedRgb(map, x, y);
    total += pixelSolidAngleSr(map.layout, map.width, map.height, y) * row;
  }
  return total;
}

glm::dvec3 sanitizedRgb(const EnvMap& map, int x, int y) {
  const glm::vec3 v = map.at(x, y);
  return goodPixel(v) ? glm::dvec3(v) : glm::dvec3(0.0);
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
