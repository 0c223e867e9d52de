// TemporalFilter: the FIR low-pass over time that keeps each light's direction and the frame's
// total power from flickering (paper 004 section 3.3, "Handling Dynamic Sequences").
//
// - Per light identity (Light::id) the filter keeps a ring of its last K directions, K =
// taps.size(),
//   indexed by frame sequence number; one more ring keeps the frames' total power
//   LightSet::luminanceSr (map units x sr). Slot of frame s: s % K. State over time is only this.
// - Direction: dir = normalise(sum_k w_k dir(t - k)) in the world frame of env_map.h. When that
//   weighted mean is shorter than kMinMeanLength (opposite directions cancel, e.g. an antipodal
//   flip), the newest direction is used, so every output direction is a finite unit vector.
// - Power: P = max(0, sum_k w_k P(t - k)). The taps sum to 1, so a constant power passes unchanged.
//   Negative taps can push the sum below 0 for a few frames after a sudden drop: it is clamped to
//   0.
// - Colour: each light carries rgbPerPower = rgb / luminanceSr of its newest lit frame (its chroma
//   times its share of the power, 1/N), and outputs rgb = P * rgbPerPower. For a set that keeps the
//   LightSet contract (every light carries luminanceSr / N) this is (P / N) * chroma, and the
//   output luminances sum to P. Each identity depends on its own input and the power only, so
//   filtering the first k lights of every frame gives exactly the first k lights of the filtered
//   output.
// - A black frame (luminanceSr = 0) or an unlit light: its direction is meaningless, so the light
//   holds its last direction and its last rgbPerPower while 0 enters the power ring. An id never
//   seen lit has rgbPerPower 0: it stays dark until its first lit frame (no grey pop-in).
// - Sequence numbers: the first frame fills every slot with itself (a static input is output
//   unchanged from frame 0). A duplicate seq replaces the newest frame. A gap of g < K missing
//   frames is filled by holding the last frame; g >= K resets the filter. A seq older than the
//   newest is rejected and changes nothing. A light id without history (the count grew), or absent
//   for >= K frames, starts with its ring filled by its current direction.
// - Delay: the output stands for the input delayFrames() frames ago (group delay at DC).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "core/fir_design.h"
#include "core/light.h"

namespace vem {

// A weighted mean of unit directions shorter than this carries no reliable direction.
inline constexpr double kMinMeanLength = 1e-3;

enum class FrameEvent {
  Started,            // first frame: the history is filled with it
  Accepted,           // seq = newest + 1
  DuplicateReplaced,  // seq = newest: it replaced the newest frame
  GapHeld,            // 1 ..= K - 1 frames were missing: the last frame was held in their slots
  ResetAfterGap,      // K or more frames were missing: the filter restarted from this frame
  StaleRejected,      // seq < newest: ignored, the state is unchanged
};

struct FilterResult {
  FrameEvent event = FrameEvent::Started;
  std::uint64_t missedFrames = 0;  // frames missing before this one (GapHeld, ResetAfterGap)
  std::optional<LightSet> lights;  // nullopt only for StaleRejected: publish nothing
};

class TemporalFilter {
 public:
  explicit TemporalFilter(FirTaps taps);

  // Feeds frame number `seq` (lights in id order, as the sampler gives them) and returns the
  // filtered set, or nullopt with StaleRejected.
  [[nodiscard]] FilterResult push(std::uint64_t seq, const LightSet& frame);

  // Group delay at DC, in frames: sum_k k w_k ((K - 1) / 2 for the symmetric presets).
  [[nodiscard]] double delayFrames() const;
  [[nodiscard]] const FirTaps& taps() const { return taps_; }

 private:
  struct Track {
    std::optional<std::uint64_t> lastSeq;   // newest frame written into `dirs`
    std::vector<glm::dvec3> dirs;           // ring of unit directions, slot seq % K
    std::optional<glm::dvec3> rgbPerPower;  // from the newest lit frame
  };

  // framePower: the input frame's luminanceSr; powerOut: the filtered power.
  [[nodiscard]] Light filterLight(std::uint64_t seq, const Light& light, double framePower,
                                  double powerOut);
  [[nodiscard]] glm::dvec3 meanDirection(const Track& track) const;
  [[nodiscard]] double filteredPower(std::uint64_t seq) const;

  FirTaps taps_;
  std::optional<std::uint64_t> newestSeq_;
  std::vector<double> powers_;          // ring of frame powers (luminanceSr), slot seq % K
  std::vector<Track> tracks_;           // indexed by light id (ids are pattern indices: dense)
  std::vector<std::size_t> slotsBack_;  // this frame's ring slot of frame seq - k, k = 0 .. K - 1
};

}  // namespace vem
