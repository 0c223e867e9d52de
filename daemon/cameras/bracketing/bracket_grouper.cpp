#include "cameras/bracketing/bracket_grouper.h"

#include <cmath>
#include <utility>

#include "util/contract.h"

namespace vem::cameras {

BracketGrouper::BracketGrouper(std::vector<double> effectiveExposuresUs, double matchTolerance)
    : exposuresUs_(std::move(effectiveExposuresUs)), tolerance_(matchTolerance) {
  VEM_EXPECTS(exposuresUs_.size() >= 2 && tolerance_ > 0.0);
}

std::optional<std::size_t> BracketGrouper::match(double effectiveExposureUs) const {
  for (std::size_t k = 0; k < exposuresUs_.size(); ++k) {
    if (std::abs(effectiveExposureUs / exposuresUs_[k] - 1.0) <= tolerance_) return k;
  }
  return std::nullopt;
}

GroupStep BracketGrouper::offer(std::uint64_t seq, double effectiveExposureUs) {
  GroupStep step;
  if (pending_ > 0 && lastSeq_ && seq != *lastSeq_ + 1) {
    step.dropPending = std::exchange(pending_, 0);
    step.pendingReason = BracketDropReason::Gap;
  }
  lastSeq_ = seq;
  const std::optional<std::size_t> index = match(effectiveExposureUs);
  if (index && *index == pending_) {
    step.keepFrame = true;
  } else {
    if (pending_ > 0) {
      step.dropPending = std::exchange(pending_, 0);
      step.pendingReason = BracketDropReason::OutOfCycle;
    }
    step.keepFrame = index == std::size_t{0};
  }
  if (step.keepFrame && ++pending_ == exposuresUs_.size()) {
    step.complete = true;
    pending_ = 0;
  }
  return step;
}

std::size_t BracketGrouper::reset() {
  lastSeq_.reset();
  return std::exchange(pending_, 0);
}

}  // namespace vem::cameras
