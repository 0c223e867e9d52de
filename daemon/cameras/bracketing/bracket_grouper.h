// BracketGrouper: which frames of a bracketing camera form complete exposure groups. Pure state
// over the frames' sequence numbers and reported exposures; it holds no frames (the caller does).
//
// Cameras apply an exposure request a few frames late, so grouping goes by the exposure each frame
// reports (exposureUs x gain), never by what was requested. A group is K frames with consecutive
// seq (no gap) whose effective exposures match bracket exposures 0, 1, .., K-1 in that order
// within the relative tolerance (bracket_settings.h). Each offered frame:
// - a seq gap (seq != previous seq + 1) breaks the group in progress: its frames are dropped for
//   Gap; then the frame is placed as below;
// - the frame matches exposure j == frames in the group so far: it joins the group; when that makes
//   K frames the group is complete (and the next frame starts afresh);
// - otherwise the group in progress is dropped for OutOfCycle, and the frame starts a new group if
//   it matches exposure 0, else it is dropped itself for OutOfCycle.
// reset() drops the group in progress (an error from the camera): the caller counts it as Error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vem::cameras {

enum class BracketDropReason { OutOfCycle, Gap, Error };

// What to do with the group in progress and the offered frame.
struct GroupStep {
  std::size_t dropPending = 0;  // drop this many frames of the group in progress first ...
  BracketDropReason pendingReason = BracketDropReason::OutOfCycle;  // ... for this reason
  bool keepFrame = false;  // the frame joins (or starts) the group; false: drop it (OutOfCycle)
  bool complete = false;   // the group now holds K frames: merge it
};

class BracketGrouper {
 public:
  // effectiveExposuresUs[k] = bracket exposure k x gain; tolerance relative (bracket_settings.h).
  BracketGrouper(std::vector<double> effectiveExposuresUs, double matchTolerance);

  [[nodiscard]] GroupStep offer(std::uint64_t seq, double effectiveExposureUs);
  // Forgets the group in progress and the last seq; returns how many frames it held.
  std::size_t reset();

  // The bracket exposure index `effectiveExposureUs` matches, or nullopt.
  [[nodiscard]] std::optional<std::size_t> match(double effectiveExposureUs) const;
  [[nodiscard]] std::size_t pendingFrames() const { return pending_; }
  [[nodiscard]] std::size_t count() const { return exposuresUs_.size(); }
  [[nodiscard]] std::span<const double> effectiveExposuresUs() const { return exposuresUs_; }

 private:
  std::vector<double> exposuresUs_;
  double tolerance_;
  std::size_t pending_ = 0;
  std::optional<std::uint64_t> lastSeq_;
};

}  // namespace vem::cameras
