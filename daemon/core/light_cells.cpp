#include "core/light_cells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/common.hpp>

#include "util/contract.h"

namespace vem {
namespace {

struct Splitter {
  std::span<const glm::dvec2> points;
  std::vector<LightCell>& out;

  double coord(bool alongA, std::uint32_t i) const { return alongA ? points[i].x : points[i].y; }

  // By the coordinate, then the index: a strict order, so the cells do not depend on the sort.
  void sortAlong(bool alongA, std::span<std::uint32_t> ids) const {
    std::sort(ids.begin(), ids.end(), [&](std::uint32_t l, std::uint32_t r) {
      return coord(alongA, l) != coord(alongA, r) ? coord(alongA, l) < coord(alongA, r) : l < r;
    });
  }

  // How far the cut after the m-th point (at m / n of the side) lies outside the gap between the
  // m-th and the (m + 1)-th point sorted along it: 0 when it passes between them.
  double violation(const LightCell& cell, bool alongA, std::span<const std::uint32_t> ids,
                   std::size_t m) const {
    const double lo = alongA ? cell.a0 : cell.b0;
    const double length = alongA ? cell.a1 - cell.a0 : cell.b1 - cell.b0;
    const double line = lo + length * double(m) / double(ids.size());
    return std::max({0.0, coord(alongA, ids[m - 1]) - line, line - coord(alongA, ids[m])});
  }

  // The count m in [1, n) with the smallest violation, the nearest n / 2 among equals.
  std::pair<std::size_t, double> bestCount(const LightCell& cell, bool alongA,
                                           std::span<const std::uint32_t> ids) const {
    const std::size_t n = ids.size(), half = n / 2;
    std::pair<std::size_t, double> best{half, violation(cell, alongA, ids, half)};
    for (std::size_t d = 1; d < n && best.second > 0; ++d) {
      for (const std::size_t m : {half - std::min(half, d), half + d}) {
        if (m < 1 || m >= n) continue;
        const double v = violation(cell, alongA, ids, m);
        if (v < best.second) best = {m, v};
      }
      if (half <= d && half + d >= n) break;
    }
    return best;
  }

  // Cuts `cell` (its light field unused) holding points ids[0..n) into leaves.
  void split(LightCell cell, std::span<std::uint32_t> ids) {
    const std::size_t n = ids.size();
    if (n == 1) {
      cell.light = ids[0];
      out.push_back(cell);
      return;
    }
    // Across the longer side if some m there keeps every point on its side, else across the
    // shorter one; where neither can, the cut that leaves its points the least outside.
    const bool longerIsA = cell.a1 - cell.a0 >= cell.b1 - cell.b0;
    sortAlong(longerIsA, ids);
    const auto longer = bestCount(cell, longerIsA, ids);
    bool alongA = longerIsA;
    std::size_t m = longer.first;
    if (longer.second > 0) {
      std::vector<std::uint32_t> other(ids.begin(), ids.end());
      sortAlong(!longerIsA, other);
      const auto shorter = bestCount(cell, !longerIsA, other);
      if (shorter.second < longer.second) {
        std::copy(other.begin(), other.end(), ids.begin());
        alongA = !longerIsA;
        m = shorter.first;
      }
    }
    const double lo = alongA ? cell.a0 : cell.b0;
    const double length = alongA ? cell.a1 - cell.a0 : cell.b1 - cell.b0;
    LightCell first = cell, second = cell;
    const double line = lo + length * double(m) / double(n);
    (alongA ? first.a1 : first.b1) = line;
    (alongA ? second.a0 : second.b0) = line;
    split(first, ids.first(m));
    split(second, ids.subspan(m));
  }
};

// The integral over [r0, r1] of row y's tent weight (of H rows): 0 at r = y - 0.5, 1 at the row's
// centre y + 0.5, 0 at y + 1.5; the first row's weight is 1 from r = 0 to its centre and the last
// row's from its centre to H, where the Havran sampler's density is constant. Each row's weight
// integrates to 1 over [0, H].
double tentWeight(int y, int height, double r0, double r1) {
  // Most rows of a cell lie wholly inside it.
  const double lowest = y == 0 ? 0.0 : y - 0.5, highest = y == height - 1 ? height : y + 1.5;
  if (r0 <= lowest && highest <= r1) return 1.0;
  const double centre = y + 0.5;
  // min and max rather than branches: this runs for every row of every cell.
  auto clamp01 = [](double v) { return std::min(1.0, std::max(0.0, v)); };
  auto cumulative = [&](double r) {
    const double rising = clamp01(r - (centre - 1));
    const double falling = clamp01(r - centre);
    const double left = y == 0 ? std::min(centre, std::max(0.0, r)) : 0.5 * rising * rising;
    const double right = y == height - 1 ? std::min(0.5, std::max(0.0, r - centre))
                                         : falling - 0.5 * falling * falling;
    return left + right;
  };
  return cumulative(r1) - cumulative(r0);
}

}  // namespace

LightCells buildLightCells(std::span<const glm::dvec2> warpPoints) {
  LightCells result;
  result.count = warpPoints.size();
  if (warpPoints.empty()) return result;
  std::vector<glm::dvec2> points(warpPoints.begin(), warpPoints.end());
  for (glm::dvec2& p : points) p = glm::clamp(p, 0.0, 1.0);
  std::vector<std::uint32_t> ids(points.size());
  std::iota(ids.begin(), ids.end(), 0U);
  result.cells.reserve(points.size());
  Splitter{points, result.cells}.split({0.0, 1.0, 0.0, 1.0, 0, 0, 0}, ids);
  for (const LightCell& cell : result.cells) {
    result.aEdges.push_back(cell.a0);
    result.aEdges.push_back(cell.a1);
  }
  std::sort(result.aEdges.begin(), result.aEdges.end());
  result.aEdges.erase(std::unique(result.aEdges.begin(), result.aEdges.end()), result.aEdges.end());
  auto edgeIndex = [&](double a) {
    return std::uint32_t(std::lower_bound(result.aEdges.begin(), result.aEdges.end(), a) -
                         result.aEdges.begin());
  };
  for (LightCell& cell : result.cells) {
    cell.a0Edge = edgeIndex(cell.a0);
    cell.a1Edge = edgeIndex(cell.a1);
  }
  return result;
}

namespace {

// The rgb of one row over b in [0, x), x its conditional (the fraction of the row's importance to
// the left, floor included), straight from the tables: the block holding x is found by walking
// from the block found in the previous row, which the smooth maps keep near (so no per-frame index
// is built), and the colour is linear within the block, as the importance is.
class RowRgb {
 public:
  explicit RowRgb(const SamplingTables& t) : t_(t), blocks_(std::size_t(t.blocksPerRow)) {}

  [[nodiscard]] double massAt(std::size_t y, std::size_t block) const {
    return t_.massAtBlock(int(y), int(block));
  }

  // The row's rgb (map units, floor as grey, no solid angle) over b in [0, x); `hint` is the block
  // to start from (kNoHint: a binary search), left at the block holding x.
  static constexpr std::size_t kNoHint = ~std::size_t(0);
  [[nodiscard]] glm::dvec3 upTo(std::size_t y, double x, std::size_t& hint) const {
    const double target = std::clamp(x, 0.0, 1.0) * massAt(y, blocks_);
    std::size_t b = 0;
    if (hint == kNoHint) {  // the last block whose start is at or before the target
      std::size_t lo = 0, hi = blocks_ - 1;
      while (lo < hi) {
        const std::size_t mid = (lo + hi + 1) / 2;
        if (massAt(y, mid) <= target) lo = mid; else hi = mid - 1;
      }
      b = lo;
    } else {
      b = hint;
      while (b > 0 && massAt(y, b) > target) --b;
      while (b + 1 < blocks_ && massAt(y, b + 1) <= target) ++b;
    }
    hint = b;
    const double m0 = massAt(y, b), m1 = massAt(y, b + 1);
    // Without branches (min and max, a denominator never zero): the division's latency then
    // overlaps the next lookup's instead of waiting on a mispredicted branch.
    const double within = (target - m0) / std::max(m1 - m0, std::numeric_limits<double>::min());
    const double fraction = std::min(1.0, std::max(0.0, within));
    const double* sums = &t_.blockCumulativeYRgb[4 * (y * (blocks_ + 1) + b)];
    const glm::dvec3 at0(sums[1], sums[2], sums[3]);
    const glm::dvec3 at1(sums[5], sums[6], sums[7]);
    return at0 + fraction * (at1 - at0);
  }

 private:
  const SamplingTables& t_;
  std::size_t blocks_;
};

}  // namespace

std::vector<glm::dvec3> cellRadianceSr(const SamplingTables& t, const LightCells& cells,
                                       std::span<const glm::dvec2> rowRanges, RowWeighting rows) {
  VEM_EXPECTS(!t.black && t.totalMass > 0 && rowRanges.size() == cells.cells.size());
  std::vector<glm::dvec3> radiance(cells.count, glm::dvec3(0.0));
  const std::size_t height = std::size_t(t.height), count = cells.cells.size();
  const RowRgb row(t);
  const bool tent = rows == RowWeighting::Tent;
  // Each cell takes, from every row it overlaps, the row's weight over the cell's rows times the
  // row's rgb over the cell's range of b, times the row's pixel solid angle. Cells that follow
  // each other in k-d order over the same range of a, side by side in b (the two halves of a cut
  // across b), go down their rows together and look up each edge they share once.
  constexpr std::size_t kLongestRun = 8;
  for (std::size_t k = 0; k < count;) {
    std::size_t end = k + 1;
    while (end < count && end - k < kLongestRun &&
           cells.cells[end].a0Edge == cells.cells[k].a0Edge &&
           cells.cells[end].a1Edge == cells.cells[k].a1Edge &&
           cells.cells[end].b0 == cells.cells[end - 1].b1) {
      ++end;
    }
    const double r0 = std::clamp(rowRanges[k].x, 0.0, double(height));
    const double r1 = std::clamp(rowRanges[k].y, r0, double(height));
    // Edge e of the run: b0 of its first cell, then b1 of each; down the rows, the block holding
    // each moves little, so each row's search starts from the last row's block.
    std::array<std::size_t, kLongestRun + 1> hints;
    hints.fill(RowRgb::kNoHint);
    // Rows whose weight can be non-zero on [r0, r1]: the row itself (box), or a tent reaching half
    // a row further each way.
    const std::size_t first = std::size_t(std::max(0.0, std::floor(tent ? r0 - 0.5 : r0)));
    for (std::size_t y = first; y < height && double(y) - (tent ? 0.5 : 0.0) < r1; ++y) {
      const double weight = tent ? tentWeight(int(y), int(height), r0, r1)
                                 : std::min(r1, double(y) + 1) - std::max(r0, double(y));
      if (!(weight > 0)) continue;
      const double scale = weight * t.pixelSolidAngleSr[y];
      glm::dvec3 left = row.upTo(y, cells.cells[k].b0, hints[0]);
      for (std::size_t j = k; j < end; ++j) {
        const glm::dvec3 right = row.upTo(y, cells.cells[j].b1, hints[j - k + 1]);
        radiance[cells.cells[j].light] += scale * (right - left);
        left = right;
      }
    }
    k = end;
  }
  return radiance;
}

}  // namespace vem
