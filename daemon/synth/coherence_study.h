// The coherence study (issue 19, `vemtool coherence` and the benchmark report): how far the lights
// jump from frame to frame over a map sequence (map_sequences.h), how much the irradiance they give
// flickers against the change of the exact irradiance, and how accurate they stay, per sampler and
// temporal-filter preset. Pure: the caller loads the maps and prints the figures.
//
// The steps that are done once per sequence are separate, so a caller shares them:
//   exactIrradiance (per sequence, the expensive part) -> sampleSequence (per sampler) ->
//   filterSequence (per preset) -> tallySequence -> CoherenceTally::add over sequences ->
//   summarise.
//
// Flicker, on luminance irradiance at the normals (light_coherence.h), over consecutive frames:
//   lights  sqrt(sum (E_L(t) - E_L(t-1))^2) / sqrt(sum E_X(t)^2)
//   exact   the same for the exact irradiance E_X of the map
//   excess  sqrt(sum ((E_L(t) - E_L(t-1)) - (E_X(t) - E_X(t-1)))^2) / sqrt(sum E_X(t)^2):
//           what the lights change beyond what the light itself did
// each summed over the normals and the frame pairs. Accuracy: the mean over frames of the relative
// RMS irradiance error (irradiance.h).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/fir_design.h"
#include "core/light.h"
#include "core/light_coherence.h"
#include "core/light_generator.h"
#include "synth/map_sequences.h"

namespace vem::synth {

// The exact irradiance of every frame's map at the normals.
[[nodiscard]] std::vector<std::vector<glm::dvec3>> exactIrradiance(
    std::span<const SequenceFrame> frames, std::span<const glm::dvec3> normals);

// The first lightCount lights of the default pattern through `sampler`, every frame, unfiltered.
// importanceWeight below 1 is issue 19's "smooth the importance in time" idea, as an experiment:
// each frame's tables come from an exponential moving average of the maps (weight importanceWeight
// on the newest), the lights' colours from the newest map, and their sum is scaled to the newest
// map's luminance integral. importanceGate > 0 gates that average by change: a pixel whose
// luminance differs from its average by more than importanceGate (relative to the larger of the
// two) takes the newest value at once, so that what moves or switches on is not dragged behind
// while the sensor noise of what stands still is averaged away.
// liftFraction > 0 is issue 19's "density floor" idea with a floor relative to the local
// brightness, also an experiment: before its tables are built, every pixel's importance is raised
// to at least liftFraction times the mean luminance of the (2 liftRadiusPx + 1)^2 pixels around it
// (liftImportance), so the dark gaps between bright regions are no longer nearly empty; the lights
// are scaled to the newest map's luminance integral as above.
[[nodiscard]] std::vector<LightSet> sampleSequence(std::span<const SequenceFrame> frames,
                                                   SamplerKind sampler, std::size_t lightCount,
                                                   double importanceWeight = 1.0,
                                                   double importanceGate = 0.0,
                                                   double liftFraction = 0.0,
                                                   int liftRadiusPx = 8);

// The map with grey added where a pixel's luminance is below `fraction` times the box mean of the
// luminance around it (radius `radiusPx`, wrapping across the columns, clamped at the first and
// last rows), up to that level. Bad pixels count as black.
[[nodiscard]] EnvMap liftImportance(const EnvMap& map, double fraction, int radiusPx);

// The sets through a fresh temporal filter with the preset's taps, frame k as sequence number k.
[[nodiscard]] std::vector<LightSet> filterSequence(std::span<const LightSet> sets,
                                                   FilterPreset preset);

// Sums over frames (and, through add, over sequences).
struct CoherenceTally {
  std::vector<double> stepsDeg;
  double lightsChangeSq = 0.0;
  double exactChangeSq = 0.0;
  double excessChangeSq = 0.0;
  double exactSq = 0.0;  // over the frames that have a previous one
  double errorSum = 0.0;
  std::size_t frames = 0;
  void add(const CoherenceTally& other);
};

[[nodiscard]] CoherenceTally tallySequence(std::span<const SequenceFrame> frames,
                                           std::span<const LightSet> sets,
                                           std::span<const std::vector<glm::dvec3>> exact,
                                           std::span<const glm::dvec3> normals);

struct CoherenceFigures {
  StepSummary steps;
  double lightsFlicker = 0.0;
  double exactFlicker = 0.0;
  double excessFlicker = 0.0;
  double meanError = 0.0;
};
[[nodiscard]] CoherenceFigures summarise(const CoherenceTally& tally);

}  // namespace vem::synth
