#include "core/temporal_filter.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "util/contract.h"

namespace vem {
namespace {

std::size_t slotOf(std::uint64_t seq, std::size_t ringSize) { return std::size_t(seq % ringSize); }

// Slot of frame seq - back, for 0 <= back < ringSize; safe when seq < back (frame 0 fills all).
std::size_t slotBack(std::uint64_t seq, std::size_t back, std::size_t ringSize) {
  return (slotOf(seq, ringSize) + ringSize - back) % ringSize;
}

// Writes `value` as frame `seq` of a ring whose newest frame is `lastSeq` (seq >= lastSeq).
// No history, or K or more missing frames: every slot takes `value`. Fewer missing frames: their
// slots hold the value of frame lastSeq. seq == lastSeq: the newest slot is replaced.
template <class T>
void writeHeld(std::vector<T>& ring, std::optional<std::uint64_t> lastSeq, std::uint64_t seq,
               const T& value) {
  const std::size_t k = ring.size();
  if (!lastSeq || seq - *lastSeq > k) {
    std::ranges::fill(ring, value);
    return;
  }
  const T held = ring[slotOf(*lastSeq, k)];
  for (std::uint64_t missing = *lastSeq + 1; missing < seq; ++missing)
    ring[slotOf(missing, k)] = held;
  ring[slotOf(seq, k)] = value;
}

FilterResult classify(std::optional<std::uint64_t> newestSeq, std::uint64_t seq, std::size_t k) {
  if (!newestSeq) return {FrameEvent::Started, 0, std::nullopt};
  if (seq < *newestSeq) return {FrameEvent::StaleRejected, 0, std::nullopt};
  if (seq == *newestSeq) return {FrameEvent::DuplicateReplaced, 0, std::nullopt};
  const std::uint64_t missed = seq - *newestSeq - 1;
  if (missed == 0) return {FrameEvent::Accepted, 0, std::nullopt};
  return {missed < k ? FrameEvent::GapHeld : FrameEvent::ResetAfterGap, missed, std::nullopt};
}

}  // namespace

TemporalFilter::TemporalFilter(FirTaps taps) : taps_(std::move(taps)), powers_(taps_.size(), 0.0) {}

double TemporalFilter::delayFrames() const { return groupDelayFramesAt(taps_, 0.0); }

FilterResult TemporalFilter::push(std::uint64_t seq, const LightSet& frame) {
  VEM_EXPECTS(std::isfinite(frame.luminanceSr) && frame.luminanceSr >= 0.0);
  // Every light has a direction (filterLight normalises it): checked once here, not per light.
  VEM_EXPECTS(std::ranges::none_of(
      frame.lights, [](const Light& light) { return light.dir == glm::vec3(0.0F); }));
  FilterResult result = classify(newestSeq_, seq, taps_.size());
  if (result.event == FrameEvent::StaleRejected) return result;
  // After a long gap every ring restarts anyway (writeHeld); clearing also forgets ids that left.
  if (result.event == FrameEvent::ResetAfterGap) tracks_.clear();
  writeHeld(powers_, newestSeq_, seq, frame.luminanceSr);
  newestSeq_ = seq;
  slotsBack_.resize(taps_.size());
  for (std::size_t back = 0; back < taps_.size(); ++back)
    slotsBack_[back] = slotBack(seq, back, taps_.size());

  LightSet out;
  out.luminanceSr = filteredPower(seq);
  out.black = out.luminanceSr == 0.0;
  out.lights.reserve(frame.lights.size());
  for (const Light& light : frame.lights) {
    out.lights.push_back(filterLight(seq, light, frame.luminanceSr, out.luminanceSr));
  }
  result.lights = std::move(out);
  return result;
}

Light TemporalFilter::filterLight(std::uint64_t seq, const Light& light, double framePower,
                                  double powerOut) {
  if (light.id >= tracks_.size()) tracks_.resize(std::size_t(light.id) + 1);
  Track& track = tracks_[light.id];
  const std::size_t k = taps_.size();
  if (track.dirs.empty()) track.dirs.resize(k);
  const bool lit = framePower > 0.0 && luminance(light.rgb) > 0.0;
  const bool live = track.lastSeq && seq - *track.lastSeq <= k;
  const glm::dvec3 dir = (lit || !live) ? glm::normalize(glm::dvec3(light.dir))
                                        : track.dirs[slotOf(*track.lastSeq, k)];
  writeHeld(track.dirs, track.lastSeq, seq, dir);
  track.lastSeq = seq;
  if (lit) track.rgbPerPower = glm::dvec3(light.rgb) / framePower;

  const glm::dvec3 rgb = powerOut * track.rgbPerPower.value_or(glm::dvec3(0.0));
  return Light{light.id, glm::vec3(meanDirection(track)), glm::vec3(rgb)};
}

glm::dvec3 TemporalFilter::meanDirection(const Track& track) const {
  const std::vector<double>& w = taps_.weights();
  glm::dvec3 sum(0.0);
  for (std::size_t back = 0; back < w.size(); ++back) sum += w[back] * track.dirs[slotsBack_[back]];
  const double length = glm::length(sum);
  if (!(length >= kMinMeanLength)) return track.dirs[slotsBack_[0]];
  return sum / length;
}

double TemporalFilter::filteredPower(std::uint64_t seq) const {
  const std::vector<double>& w = taps_.weights();
  double sum = 0.0;
  for (std::size_t back = 0; back < w.size(); ++back) {
    sum += w[back] * powers_[slotBack(seq, back, w.size())];
  }
  return std::max(0.0, sum);
}

}  // namespace vem
