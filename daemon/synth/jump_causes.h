// Why a light jumps (issue 19): for every light whose step between two frames is larger than
// kLargeStepDeg, where the step took it in the tables of the newer frame. Either its row coordinate
// moved by a row or more (the inverse of the marginal over rows moved: a jump across rows), or it
// stayed in its row and its column moved (the inverse of the row's conditional moved: a jump along
// the row). Either way, how bright the stretch it passed over is, against the mean: an inverse CDF
// is steep wherever the density is nearly zero, so a point whose CDF value sits at the level of a
// dark gap crosses the whole gap when the mass on one side changes a little.
//
// A diagnosis for `vemtool coherence --explain-jumps` and docs/temporal-filter.md; pure.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>

#include "core/light.h"
#include "core/sampling_tables.h"

namespace vem::synth {

struct LargeJump {
  double stepDeg = 0.0;
  bool acrossRows = false;  // the row coordinate moved by one row or more
  // Mean importance of what the jump passed over, over the mean importance: along a row, the
  // luminance of the row's pixels strictly between the two columns over the row's mean; across
  // rows, the mass of the rows strictly between over the mean row mass. 1 when nothing lies
  // strictly between.
  double gapRatio = 1.0;
  // The brightest 16-pixel block's share of its row's importance (the newer row): near 1 when the
  // row holds a sun, whose noise then shifts the row's whole conditional CDF, and with it every
  // point in the dimmer rest of the row.
  double rowPeakShare = 0.0;
  // |F0(x) - F1(x)|: how far apart the conditional CDFs (fractions of each row's importance left
  // of the point's column) of the two rows whose centres bracket the newer point are. Havran's
  // sampler blends those two rows by the point's row coordinate, so where they disagree a small
  // shift of the marginal moves the column far; the standard sampler switches between them when the
  // point crosses a row edge.
  double neighbourRowsDisagree = 0.0;
  bool rowIndexChanged = false;  // the point's row (floor of its row coordinate) changed
};

// Appends a LargeJump for every id lit in both sets whose step beyond `motion` (as
// appendAngularStepsDeg) exceeds kLargeStepDeg; `tables` are the current frame's.
void appendLargeJumps(const SamplingTables& tables, const LightSet& previous,
                      const LightSet& current, const glm::dmat3& motion,
                      std::vector<LargeJump>& out);

// The brightest block's share of the row of every lit light of `set` (as LargeJump::rowPeakShare):
// how common such rows are among all the lights, against which the jumps' rows compare.
void appendRowPeakShares(const SamplingTables& tables, const LightSet& set,
                         std::vector<double>& out);
// LargeJump::neighbourRowsDisagree for every lit light of `set`, for the same comparison.
void appendNeighbourRowsDisagreement(const SamplingTables& tables, const LightSet& set,
                                     std::vector<double>& out);
inline constexpr double kRowsDisagree = 0.1;

inline constexpr double kPeakyRowShare = 0.5;  // a row whose brightest block holds more than this

struct JumpCauses {
  std::size_t count = 0;
  double fractionAcrossRows = 0.0;
  double fractionGapBelowPercent = 0.0;   // gapRatio < 0.01
  double fractionGapBelowTenPercent = 0.0;  // gapRatio < 0.1
  double medianGapRatio = 0.0;
  double fractionPeakyRow = 0.0;  // rowPeakShare > kPeakyRowShare
  double fractionRowsDisagree = 0.0;  // neighbourRowsDisagree > kRowsDisagree
  double fractionRowIndexChanged = 0.0;
};
[[nodiscard]] JumpCauses summariseJumps(std::span<const LargeJump> jumps);

}  // namespace vem::synth
