#include "core/sampling_tables.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "core/color.h"

namespace vem {
namespace {

void resizeFor(SamplingTables& t, const EnvMap& map) {
  t.layout = map.layout;
  t.width = map.width;
  t.height = map.height;
  t.blocksPerRow = (map.width + kColumnBlock - 1) / kColumnBlock;
  t.pixelLuminance.resize(map.pixelCount());
  t.blockCumulativeYRgb.resize(4 * std::size_t(map.height) * std::size_t(t.blocksPerRow + 1));
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

// Adds the pixel's rgb to sums[0..3) if pixelLuminance() keeps it.
inline void addIfGood(const float* rgb, float* sums) {
  unsigned bad = 0;
  pixelLuminance(rgb, bad);
  if (bad == 0) {
    for (int c = 0; c < 3; ++c) sums[c] += rgb[c];
  }
}

// Four pixels at a time with GCC's generic vectors (SSE2 on x86-64, NEON on ARM): the interleaved
// RGB of four pixels is split into R, G and B lanes, and the same test as pixelLuminance() keeps or
// zeroes each pixel. The scalar loop costs about 24 instructions a pixel; this, about 8.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int __attribute__((vector_size(16)));

// An unaligned vector load (one movups): GCC splits a memcpy into a vector into scalar loads here.
using UnalignedFloat4 = float __attribute__((vector_size(16), aligned(4), may_alias));
inline Float4 loadFloat4(const float* p) { return *reinterpret_cast<const UnalignedFloat4*>(p); }

// Per channel, four lanes of sums.
struct Rgb4 {
  Float4 r{0, 0, 0, 0};
  Float4 g{0, 0, 0, 0};
  Float4 b{0, 0, 0, 0};
};

// Luminances of pixels rgb[0..3] (12 floats); subtracts 1 from `goodLanes` for each good pixel and
// adds all four pixels' channels to `sums` (the caller sums a block with a bad pixel again).
inline Float4 luminance4(const float* rgb, Int4& goodLanes, Rgb4& sums) {
  const Float4 a = loadFloat4(rgb), b = loadFloat4(rgb + 4), c = loadFloat4(rgb + 8);
  // a = r0 g0 b0 r1, b = g1 b1 r2 g2, c = b2 r3 g3 b3
  const Float4 ab0 = __builtin_shuffle(a, b, Int4{0, 3, 6, 0});
  const Float4 ab1 = __builtin_shuffle(a, b, Int4{1, 4, 7, 0});
  const Float4 ab2 = __builtin_shuffle(a, b, Int4{2, 5, 0, 0});
  const Float4 r = __builtin_shuffle(ab0, c, Int4{0, 1, 2, 5});
  const Float4 g = __builtin_shuffle(ab1, c, Int4{0, 1, 2, 6});
  const Float4 bl = __builtin_shuffle(ab2, c, Int4{0, 1, 4, 7});
  const Float4 y = float(kRec709R) * r + float(kRec709G) * g + float(kRec709B) * bl;
  const Float4 smallest = r < g ? r : g;
  const Float4 lowest = smallest < bl ? smallest : bl;
  const Int4 good = (lowest >= 0.0F) & (y <= std::numeric_limits<float>::max());  // -1 where good
  goodLanes += good;
  sums.r += r;
  sums.g += g;
  sums.b += bl;
  return good ? y : Float4{0, 0, 0, 0};
}

// Lanes 0-1 and 2-3 of v in double: one cvtps2pd each on x86-64 (the luminance is summed in double
// so that a sun of 1e8 does not swallow the sky beside it in its block).
using Double2 = double __attribute__((vector_size(16)));
inline Double2 lowHalfToDouble(Float4 v) {
#ifdef __SSE2__
  return Double2(_mm_cvtps_pd(__m128(v)));
#else
  return Double2{double(v[0]), double(v[1])};
#endif
}
inline Double2 highHalfToDouble(Float4 v) {
#ifdef __SSE2__
  return Double2(_mm_cvtps_pd(_mm_movehl_ps(__m128(v), __m128(v))));
#else
  return Double2{double(v[2]), double(v[3])};
#endif
}

inline float laneSum(Float4 v) { return (v[0] + v[1]) + (v[2] + v[3]); }

// One row in one pass: each pixel's luminance into `luminance`, the sums at block edges into
// `yRgbSums` (4 per edge: the luminance and the rgb, in double). Returns the number of bad pixels.
std::size_t accumulateRow(const float* rgb, int width, float* luminance, double* yRgbSums) {
  unsigned bad = 0;
  double base = 0;
  yRgbSums[0] = yRgbSums[1] = yRgbSums[2] = yRgbSums[3] = 0;
  int block = 0;
  for (int first = 0; first < width; first += kColumnBlock) {
    const int last = std::min(width, first + kColumnBlock);
    Double2 sumLow{0, 0}, sumHigh{0, 0};  // four chains of additions instead of one long one
    Int4 goodLanes{0, 0, 0, 0};
    Rgb4 channels;
    int x = first;
    for (; x + 4 <= last; x += 4) {
      const Float4 y = luminance4(rgb + 3 * x, goodLanes, channels);
      std::memcpy(luminance + x, &y, sizeof y);
      sumLow += lowHalfToDouble(y);
      sumHigh += highHalfToDouble(y);
    }
    const unsigned badInVectors =
        unsigned((x - first) + goodLanes[0] + goodLanes[1] + goodLanes[2] + goodLanes[3]);
    bad += badInVectors;
    float tailRgb[3] = {0, 0, 0};
    if (badInVectors > 0) {  // rare: the block's colour again, without its bad pixels
      channels = Rgb4{};
      for (int p = first; p < x; ++p) addIfGood(rgb + 3 * p, tailRgb);
    }
    double tail = 0;
    for (; x < last; ++x) {
      luminance[x] = pixelLuminance(rgb + 3 * x, bad);
      tail += double(luminance[x]);
      addIfGood(rgb + 3 * x, tailRgb);
    }
    base += ((sumLow[0] + sumLow[1]) + (sumHigh[0] + sumHigh[1])) + tail;
    double* sums = yRgbSums + 4 * block;
    sums[4] = base;
    sums[5] = sums[1] + double(laneSum(channels.r) + tailRgb[0]);
    sums[6] = sums[2] + double(laneSum(channels.g) + tailRgb[1]);
    sums[7] = sums[3] + double(laneSum(channels.b) + tailRgb[2]);
    ++block;
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
    t.rowMass[std::size_t(y)] = t.pixelSolidAngleSr[std::size_t(y)] * t.massAtBlock(y, t.blocksPerRow);
    t.boxCdf[std::size_t(y) + 1] = t.boxCdf[std::size_t(y)] + t.rowMass[std::size_t(y)];
  }
  // Tent marginal: half a row of constant density at each end, trapezoids between row centres.
  t.tentCdf[0] = 0;
  t.tentCdf[1] = 0.5 * t.rowMass[0];
  for (int j = 1; j < h; ++j) {
    t.tentCdf[std::size_t(j) + 1] =
        t.tentCdf[std::size_t(j)] +
        0.5 * (t.rowMass[std::size_t(j) - 1] + t.rowMass[std::size_t(j)]);
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
    const std::size_t row = std::size_t(y);
    double* sums = &t.blockCumulativeYRgb[4 * row * std::size_t(t.blocksPerRow + 1)];
    t.badPixels += accumulateRow(&map.rgb[3 * row * std::size_t(map.width)], map.width,
                                 &t.pixelLuminance[row * std::size_t(map.width)], sums);
    t.luminanceSr += omega * sums[4 * std::size_t(t.blocksPerRow)];
  }
  t.black = !(t.luminanceSr > 0);
  // Uniform importance for a black map; otherwise a floor far below anything that matters.
  t.floorY = t.black ? 1.0 : kFloorFraction * t.luminanceSr / coveredSolidAngleSr(map.layout);
  // The floor into the sums (as grey into the rgb): the samplers and the cells read it in.
  const std::size_t edges = std::size_t(t.blocksPerRow + 1);
  std::vector<double> floorAtEdge(4 * edges);
  for (std::size_t b = 0; b < edges; ++b) {
    const double floor = double(std::min(t.width, int(b) * kColumnBlock)) * t.floorY;
    for (std::size_t c = 0; c < 4; ++c) floorAtEdge[4 * b + c] = floor;
  }
  for (std::size_t row = 0; row < std::size_t(t.height); ++row) {
    double* sums = &t.blockCumulativeYRgb[4 * row * edges];
    for (std::size_t i = 0; i < 4 * edges; ++i) sums[i] += floorAtEdge[i];
  }
  buildMarginals(t);
  return t;
}

double SamplingTables::cumulativeY(int y, int x) const {
  const int block = x / kColumnBlock;
  double sum = massAtBlock(y, block) - std::min(width, block * kColumnBlock) * floorY;
  const float* row = &pixelLuminance[std::size_t(y) * std::size_t(width)];
  for (int i = block * kColumnBlock; i < x; ++i) sum += double(row[i]);
  return sum;
}

namespace {

// The blended mass of column x, floor included.
double blendedPixel(const SamplingTables& t, const RowPair& rows, int x) {
  return rows.weight0 * t.pixelY(rows.row0, x) + rows.weight1 * t.pixelY(rows.row1, x);
}

// The blended cumulative at the edge of block b (column kColumnBlock b, or the row's end).
double blendedAtBlock(const SamplingTables& t, const RowPair& rows, int block) {
  return rows.weight0 * t.massAtBlock(rows.row0, block) +
         rows.weight1 * t.massAtBlock(rows.row1, block);
}

}  // namespace

double blendedCumulative(const SamplingTables& t, const RowPair& rows, double xc) {
  const int x = std::clamp(int(xc), 0, t.width);
  const int block = x / kColumnBlock;
  double sum = blendedAtBlock(t, rows, block);
  for (int i = block * kColumnBlock; i < x; ++i) sum += blendedPixel(t, rows, i);
  return x < t.width ? sum + (xc - x) * blendedPixel(t, rows, x) : sum;
}

double invertBlendedCumulative(const SamplingTables& t, const RowPair& rows, double target) {
  // Binary search over the block edges (double sums), then a walk through one block's pixels.
  int lo = 0;
  int hi = t.blocksPerRow;  // invariant: blendedAtBlock(lo) <= target, lo < hi
  if (!(target > 0)) return 0.0;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (blendedAtBlock(t, rows, mid) <= target)
      lo = mid;
    else
      hi = mid;
  }
  double sum = blendedAtBlock(t, rows, lo);
  const int last = std::min(t.width, (lo + 1) * kColumnBlock);
  for (int x = lo * kColumnBlock; x < last; ++x) {
    const double mass = blendedPixel(t, rows, x);
    if (sum + mass > target || x == last - 1)
      return x + std::clamp((target - sum) / mass, 0.0, 1.0);
    sum += mass;
  }
  return double(t.width);
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
