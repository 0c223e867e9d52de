// The `fluorescent` scene: its 100 Hz ripple aliases to 10 Hz at 30 frames/s, and the temporal
// filter takes most of that flicker out of the frames' total power.
#include "synth/fluorescent_scene.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/fir_design.h"
#include "core/temporal_filter.h"
#include "synth/synth_pipeline.h"

namespace vem::synth {
namespace {

constexpr double kRateHz = 30.0;
constexpr int kFrames = 60;

// Relative standard deviation of `values` from index `first` on.
double relativeSpread(const std::vector<double>& values, std::size_t first) {
  double sum = 0.0;
  double sumSquares = 0.0;
  for (std::size_t i = first; i < values.size(); ++i) {
    sum += values[i];
    sumSquares += values[i] * values[i];
  }
  const double n = double(values.size() - first);
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sumSquares / n - mean * mean)) / mean;
}

// The total power (LightSet::luminanceSr) of each frame's lights, as captured.
const std::vector<LightSet>& capturedLights() {
  static const std::vector<LightSet> frames = [] {
    const FluorescentScene scene;
    std::vector<LightSet> sets;
    for (int k = 0; k < kFrames; ++k) {
      const vem::RawFrame frame =
          testing::exampleSyntheticCamera().render(scene.at(k / kRateHz), std::uint64_t(k));
      sets.push_back(
          testing::hemisphereLights(testing::calibratedMap(testing::exampleCamera(), frame), 64));
    }
    return sets;
  }();
  return frames;
}

std::vector<double> filteredPowers(const FirTaps& taps) {
  TemporalFilter filter(taps);
  std::vector<double> powers;
  for (std::size_t k = 0; k < capturedLights().size(); ++k) {
    powers.push_back(filter.push(k, capturedLights()[k]).lights->luminanceSr);
  }
  return powers;
}

TEST(FluorescentScene, RippleAliasesToAThreeFramePeriodAtThirtyHz) {
  const FluorescentScene scene;
  EXPECT_DOUBLE_EQ(scene.rippleFactor(0.0), 1.0);
  EXPECT_NEAR(scene.rippleFactor(1.0 / kRateHz), 1.0 + 0.3 * std::sqrt(0.75), 1e-9);
  EXPECT_NEAR(scene.rippleFactor(2.0 / kRateHz), 1.0 - 0.3 * std::sqrt(0.75), 1e-9);
  for (int k = 0; k < 30; ++k) {
    EXPECT_NEAR(scene.rippleFactor((k + 3) / kRateHz), scene.rippleFactor(k / kRateHz), 1e-9);
  }
}

TEST(FluorescentScene, CapturedPowerFlickersLikeTheLamps) {
  std::vector<double> raw;
  for (const LightSet& set : capturedLights()) raw.push_back(set.luminanceSr);
  // 0.3 x sqrt(1/2) for a sine sampled at three equally spaced phases.
  EXPECT_NEAR(relativeSpread(raw, 0), 0.3 * std::sqrt(0.5), 0.01);
}

TEST(FluorescentScene, TemporalFilterCutsTheAliasedFlicker) {
  std::vector<double> raw;
  for (const LightSet& set : capturedLights()) raw.push_back(set.luminanceSr);
  const std::size_t settled = 13;  // past the longest filter's start-up
  const double rawSpread = relativeSpread(raw, settled);

  // The paper's 9 taps: 10 Hz at 30 frames/s is 1/3 cycle per frame, in their transition band
  // (gain 0.431, the same as 7 Hz at 21 Hz).
  const FirTaps paper9 = presetTaps(FilterPreset::Paper9);
  const double paperRatio = relativeSpread(filteredPowers(paper9), settled) / rawSpread;
  EXPECT_NEAR(paperRatio, gainAt(paper9, 10.0 / kRateHz), 0.03);
  EXPECT_LT(paperRatio, 0.5);

  // The paper's band edges designed for 30 frames/s (13 taps, docs/temporal-filter.md): 10 Hz
  // lies in its stop band.
  const auto designed = designLowPass({13, {kRateHz, 5.88, 8.064}});
  ASSERT_TRUE(designed);
  const double designedRatio = relativeSpread(filteredPowers(*designed), settled) / rawSpread;
  EXPECT_LT(designedRatio, 1.0 / 3.0);
  std::printf(
      "power spread raw %.4f; filtered by paper9 %.4f (ratio %.3f), by a 13-tap 30 Hz "
      "design %.4f (ratio %.3f)\n",
      rawSpread, paperRatio * rawSpread, paperRatio, designedRatio * rawSpread, designedRatio);
}

}  // namespace
}  // namespace vem::synth
