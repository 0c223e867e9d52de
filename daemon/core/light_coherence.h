// How much a light set holds still from one frame to the next (issue 19): the angular step of each
// light identity between consecutive frames, and the relative frame-to-frame change of a quantity
// sampled at a few normals (the irradiance flicker). Pure measures for `vemtool coherence`, the
// benchmark report and tests; the study that runs them over map sequences is in
// daemon/synth/coherence_study.h.
//
// A light is matched across frames by its id (light.h), never by its index. Only lights lit in both
// frames (luminance > 0) have a step: an unlit light's direction means nothing. For a map that
// turns, `motion` carries the previous frame's directions to where the turning takes them, so the
// step counts only what moved beyond the true motion (the excess step).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>

#include "core/light.h"

namespace vem {

// Appends to `stepsDeg` the angle in degrees between current.dir and motion * previous.dir for
// every id lit in both sets.
void appendAngularStepsDeg(const LightSet& previous, const LightSet& current,
                           const glm::dmat3& motion, std::vector<double>& stepsDeg);

// The distribution of steps (degrees): median, 99th percentile (nearest rank), largest, and the
// fraction above kLargeStepDeg. All 0 for no steps.
inline constexpr double kLargeStepDeg = 5.0;
struct StepSummary {
  std::size_t count = 0;
  double medianDeg = 0.0;
  double p99Deg = 0.0;
  double maxDeg = 0.0;
  double fractionLarge = 0.0;  // of the steps above kLargeStepDeg
};
[[nodiscard]] StepSummary summariseSteps(std::vector<double> stepsDeg);

// Luminance of each irradiance vector (rgb per normal), for the flicker sums.
[[nodiscard]] std::vector<double> luminances(std::span<const glm::dvec3> rgb);

}  // namespace vem
