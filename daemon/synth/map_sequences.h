// Map sequences with a known truth, for the coherence study (coherence_study.h, issue 19): each
// frame's environment map and the true motion of the world since the previous frame. Pure and
// deterministic (a seed gives the same noise).
//
// - noisySequence: the map at rest, each pixel channel times (1 + sigma n), n a fresh standard
//   normal per frame (clamped at 0), as a sensor's shot and read noise roughly do.
// - turningSequence: the map turning about +Y by degPerFrame each frame. A camera pixel integrates
//   the world over its footprint, and the world here is the map as piecewise-constant pixels, so a
//   pixel of the turned map is the footprint-weighted mean of the two source pixels it overlaps
//   (linear interpolation in azimuth, wrapping): what a camera would record, sub-pixel blur
//   included. Frame k is the map turned by k degPerFrame; motionFromPrevious turns a direction by
//   degPerFrame (phi grows, env_map.h).
// - switchOnSequence: a light switching on: the cap of kSwitchCapRadiusDeg around the map's
//   brightest pixel is dark for kSwitchOffFrames frames, then scaled from 1/kSwitchRampFrames to 1
//   over kSwitchRampFrames frames, then stays on; the rest of the map is unchanged.
// - sceneSequence: a synthetic scene (synthetic_scene.h) at rateHz, rendered straight into a map
//   (no camera): each pixel the solid-angle-weighted mean of kSceneSubsamples^2 directions inside
//   it, or of kSceneRefinedSubsamples^2 where those differ by more than kSceneRefineContrast in
//   luminance (the sun's edge, the horizon) and next to such a pixel, so that a sun smaller than a
//   pixel keeps its power
//   from frame to frame as it moves (4 x 4 samples would let it jump by tens of per cent).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>

#include "core/env_map.h"
#include "synth/synthetic_scene.h"

namespace vem::synth {

struct SequenceFrame {
  EnvMap map;
  glm::dmat3 motionFromPrevious{1.0};  // world directions at frame k-1 to where they are at k
};

inline constexpr double kSwitchCapRadiusDeg = 10.0;
inline constexpr int kSwitchOffFrames = 3;
inline constexpr int kSwitchRampFrames = 10;
inline constexpr int kSceneSubsamples = 4;
inline constexpr int kSceneRefinedSubsamples = 64;
inline constexpr double kSceneRefineContrast = 4.0;

// The rotation about +Y that increases the azimuth phi by angleDeg.
[[nodiscard]] glm::dmat3 turnAboutUp(double angleDeg);

[[nodiscard]] std::vector<SequenceFrame> noisySequence(const EnvMap& map, double sigma, int frames,
                                                       std::uint64_t seed);
[[nodiscard]] std::vector<SequenceFrame> turningSequence(const EnvMap& map, double degPerFrame,
                                                         int frames);
// frames >= kSwitchOffFrames + kSwitchRampFrames + 1.
[[nodiscard]] std::vector<SequenceFrame> switchOnSequence(const EnvMap& map, int frames);
[[nodiscard]] std::vector<SequenceFrame> sceneSequence(const SyntheticScene& scene,
                                                       MapLayout layout, int width, int height,
                                                       double rateHz, int frames);

// The map turned about +Y by angleDeg (the turningSequence's frame rule).
[[nodiscard]] EnvMap turnedMap(const EnvMap& map, double angleDeg);

}  // namespace vem::synth
