#include "synth/jump_causes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "core/color.h"
#include "core/light_coherence.h"

namespace vem::synth {
namespace {

// Mean luminance of row y's pixels strictly between columns xa and xb, over the row's mean.
double rowGapRatio(const SamplingTables& t, int y, double xa, double xb) {
  const int first = int(std::floor(std::min(xa, xb))) + 1;
  const int last = std::min(int(std::floor(std::max(xa, xb))), t.width);  // exclusive
  if (last <= first) return 1.0;
  const double rowMean = t.cumulativeY(y, t.width) / t.width;
  if (!(rowMean > 0)) return 0.0;
  const double gapMean = (t.cumulativeY(y, last) - t.cumulativeY(y, first)) / (last - first);
  return gapMean / rowMean;
}

// Mean mass of the rows strictly between row coordinates ra and rb, over the mean row mass.
double rowsGapRatio(const SamplingTables& t, double ra, double rb) {
  const int first = int(std::floor(std::min(ra, rb))) + 1;
  const int last = std::min(int(std::floor(std::max(ra, rb))), t.height);
  if (last <= first) return 1.0;
  double between = 0;
  for (int y = first; y < last; ++y) between += t.rowMass[std::size_t(y)];
  return (between / (last - first)) / (t.totalMass / t.height);
}

double rowPeakShare(const SamplingTables& t, int y) {
  const double row = t.massAtBlock(y, t.blocksPerRow);
  if (!(row > 0)) return 0.0;
  double peak = 0;
  for (int b = 0; b < t.blocksPerRow; ++b)
    peak = std::max(peak, t.massAtBlock(y, b + 1) - t.massAtBlock(y, b));
  return peak / row;
}

double conditionalAt(const SamplingTables& t, int y, double xc) {
  const double row = t.cumulativeY(y, t.width);
  const int x = std::clamp(int(xc), 0, t.width);
  return row > 0 ? t.cumulativeY(y, x) / row : double(x) / t.width;
}

double neighbourRowsDisagree(const SamplingTables& t, MapCoords c) {
  const int y0 = std::clamp(int(std::floor(c.r - 0.5)), 0, t.height - 1);
  const int y1 = std::min(y0 + 1, t.height - 1);
  return std::abs(conditionalAt(t, y0, c.xc) - conditionalAt(t, y1, c.xc));
}

}  // namespace

void appendNeighbourRowsDisagreement(const SamplingTables& tables, const LightSet& set,
                                     std::vector<double>& out) {
  for (const Light& light : set.lights) {
    if (!(luminance(light.rgb) > 0)) continue;
    out.push_back(neighbourRowsDisagree(
        tables, mapCoordsFromDirection(tables, glm::normalize(glm::dvec3(light.dir)))));
  }
}

void appendRowPeakShares(const SamplingTables& tables, const LightSet& set,
                         std::vector<double>& out) {
  for (const Light& light : set.lights) {
    if (!(luminance(light.rgb) > 0)) continue;
    const MapCoords c = mapCoordsFromDirection(tables, glm::normalize(glm::dvec3(light.dir)));
    out.push_back(rowPeakShare(tables, std::clamp(int(c.r), 0, tables.height - 1)));
  }
}

void appendLargeJumps(const SamplingTables& tables, const LightSet& previous,
                      const LightSet& current, const glm::dmat3& motion,
                      std::vector<LargeJump>& out) {
  std::unordered_map<std::uint32_t, const Light*> before;
  for (const Light& light : previous.lights) {
    if (luminance(light.rgb) > 0) before.emplace(light.id, &light);
  }
  for (const Light& light : current.lights) {
    const auto it = before.find(light.id);
    if (it == before.end() || !(luminance(light.rgb) > 0)) continue;
    const glm::dvec3 from = glm::normalize(motion * glm::dvec3(it->second->dir));
    const glm::dvec3 to = glm::normalize(glm::dvec3(light.dir));
    const double stepDeg =
        std::acos(std::clamp(glm::dot(from, to), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    if (!(stepDeg > kLargeStepDeg)) continue;
    const MapCoords a = mapCoordsFromDirection(tables, from);
    const MapCoords b = mapCoordsFromDirection(tables, to);
    LargeJump jump{stepDeg, std::abs(a.r - b.r) >= 1.0, 1.0, 0.0};
    const int row = std::clamp(int(b.r), 0, tables.height - 1);
    jump.rowPeakShare = rowPeakShare(tables, row);
    jump.neighbourRowsDisagree = neighbourRowsDisagree(tables, b);
    jump.rowIndexChanged = int(a.r) != int(b.r);
    jump.gapRatio = jump.acrossRows ? rowsGapRatio(tables, a.r, b.r)
                                    : rowGapRatio(tables, row, a.xc, b.xc);
    out.push_back(jump);
  }
}

JumpCauses summariseJumps(std::span<const LargeJump> jumps) {
  JumpCauses c;
  c.count = jumps.size();
  if (jumps.empty()) return c;
  std::vector<double> ratios;
  ratios.reserve(jumps.size());
  std::size_t across = 0, belowPercent = 0, belowTenPercent = 0, peaky = 0, disagree = 0,
              changed = 0;
  for (const LargeJump& j : jumps) {
    peaky += j.rowPeakShare > kPeakyRowShare ? 1 : 0;
    disagree += j.neighbourRowsDisagree > kRowsDisagree ? 1 : 0;
    changed += j.rowIndexChanged ? 1 : 0;
    across += j.acrossRows ? 1 : 0;
    belowPercent += j.gapRatio < 0.01 ? 1 : 0;
    belowTenPercent += j.gapRatio < 0.1 ? 1 : 0;
    ratios.push_back(j.gapRatio);
  }
  const double n = double(jumps.size());
  c.fractionAcrossRows = double(across) / n;
  c.fractionPeakyRow = double(peaky) / n;
  c.fractionRowsDisagree = double(disagree) / n;
  c.fractionRowIndexChanged = double(changed) / n;
  c.fractionGapBelowPercent = double(belowPercent) / n;
  c.fractionGapBelowTenPercent = double(belowTenPercent) / n;
  std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(ratios.size() / 2), ratios.end());
  c.medianGapRatio = ratios[ratios.size() / 2];
  return c;
}

}  // namespace vem::synth
