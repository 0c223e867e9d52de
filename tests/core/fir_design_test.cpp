#include "core/fir_design.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace vem {
namespace {

// scipy.signal.remez(9, [0, 7, 9, 10.5], [1, 0], fs=21): the paper's stated edges, equal weights.
constexpr std::array<double, 9> kScipyTapsAtStatedEdges = {
    0.02451, 0.09844, -0.15504, 0.21466, 0.76106, 0.21466, -0.15504, 0.09844, 0.02451};

double maxAbsDifference(const std::vector<double>& a, std::span<const double> b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}

TEST(FirDesign, EveryPresetsTapsSumToOne) {
  for (FilterPreset preset : kAllPresets) {
    const FirTaps taps = presetTaps(preset);
    const std::vector<double>& w = taps.weights();
    EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-12) << presetName(preset);
  }
}

TEST(FirDesign, PaperPresetIsThePublishedTapsDividedByTheirSum) {
  const FirTaps taps = presetTaps(FilterPreset::Paper9);
  const std::vector<double>& w = taps.weights();
  ASSERT_EQ(w.size(), 9U);
  EXPECT_NEAR(w[4], 0.65223 / 1.09245, 1e-12);  // w5, the centre tap
  EXPECT_NEAR(w[0], 0.06216 / 1.09245, 1e-12);  // w1 = w9
  for (std::size_t k = 0; k < 9; ++k) EXPECT_DOUBLE_EQ(w[k], w[8 - k]);
}

TEST(FirDesign, ParksMcClellanReproducesThePaperTapsAtTheEffectiveEdges) {
  const auto raw = designEquiripple({9, kPaperEffectiveEdges});
  ASSERT_TRUE(raw.has_value());
  EXPECT_LT(maxAbsDifference(*raw, kPaperTapsRaw), 1e-3);
}

TEST(FirDesign, ParksMcClellanAtThePaperStatedEdgesGivesScipysTapsNotThePapers) {
  const auto raw = designEquiripple({9, kPaperStatedEdges});
  ASSERT_TRUE(raw.has_value());
  EXPECT_LT(maxAbsDifference(*raw, kScipyTapsAtStatedEdges), 1e-3);
  EXPECT_GT(maxAbsDifference(*raw, kPaperTapsRaw), 0.03);  // the discrepancy the doc explains
}

TEST(FirDesign, DesignerRejectsEdgesItCannotDesign) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::array<LowPassSpec, 8> invalid = {{
      {9, {21.0, 9.0, 9.0}},   // pass == stop
      {9, {21.0, 9.5, 9.0}},   // pass > stop
      {9, {21.0, 7.0, 10.5}},  // stop at half the rate
      {9, {21.0, 0.0, 9.0}},   // pass at 0
      {8, {21.0, 7.0, 9.0}},   // even tap count
      {1, {21.0, 7.0, 9.0}},   // too few taps
      {9, {0.0, 7.0, 9.0}},    // no rate
      {9, {nan, 7.0, 9.0}},    // not a rate
  }};
  for (const LowPassSpec& spec : invalid) {
    EXPECT_TRUE(describeInvalid(spec).has_value()) << spec.tapCount << " " << spec.edges.passHz;
    EXPECT_FALSE(designLowPass(spec).has_value()) << spec.tapCount << " " << spec.edges.passHz;
  }
  EXPECT_FALSE(describeInvalid({9, {30.0, 5.88, 8.064}}).has_value());
}

TEST(FirDesign, NormalisingRefusesWeightsWithoutADcGain) {
  EXPECT_FALSE(FirTaps::normalised(std::vector<double>{}).has_value());
  EXPECT_FALSE(FirTaps::normalised(std::array{1.0, -1.0}).has_value());
  EXPECT_FALSE(FirTaps::normalised(std::array{1.0, std::numeric_limits<double>::infinity()}));
  EXPECT_TRUE(FirTaps::normalised(std::array{-2.0, -2.0}).has_value());
}

TEST(FirDesign, CharacteriseTwoTapAverageMatchesClosedForms) {
  // w = (1/2, 1/2): |H(f)| = |cos(pi f)|, delay 1/2 frame, half power at f = 1/4 cycle per frame.
  const FirTaps average = FirTaps::normalised(std::array{1.0, 1.0}).value();
  const FilterCharacteristics c = characteriseFilter(average, {20.0, 2.0, 8.0});
  EXPECT_NEAR(c.delayFrames, 0.5, 1e-12);
  EXPECT_NEAR(c.delayMs, 25.0, 1e-9);
  EXPECT_NEAR(c.delaySpreadFrames, 0.0, 1e-12);
  EXPECT_NEAR(c.halfPowerHz, 5.0, 1e-9);
  EXPECT_NEAR(c.passGain, std::cos(std::numbers::pi * 0.1), 1e-12);
  EXPECT_NEAR(c.stopGainMax, std::cos(std::numbers::pi * 0.4), 1e-12);
  EXPECT_NEAR(c.jitterRmsGain, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(c.stepOvershoot, 0.0);
  EXPECT_NEAR(groupDelayFramesAt(average, 0.3), 0.5, 1e-12);
}

TEST(FirDesign, PaperFilterHalvesSevenHertzAndHasAFourFrameDelay) {
  const FilterCharacteristics c =
      characteriseFilter(presetTaps(FilterPreset::Paper9), kPaperStatedEdges);
  EXPECT_NEAR(c.delayFrames, 4.0, 1e-12);
  EXPECT_NEAR(c.delaySpreadFrames, 0.0, 1e-9);
  EXPECT_NEAR(c.passGain, 0.431, 2e-3);  // 0.47 before normalising: not a 7 Hz pass edge
  EXPECT_NEAR(c.passGain * 1.09245, 0.47, 5e-3);
  EXPECT_GT(c.stopGainMax, 0.05);
  EXPECT_LT(c.stopGainMax, 0.1);
}

TEST(FirDesign, Equiripple5HalvesTheDelayAndStillStopsNineHertz) {
  const FirTaps taps = presetTaps(FilterPreset::Equiripple5);
  ASSERT_EQ(taps.size(), 5U);
  const FilterCharacteristics fast = characteriseFilter(taps, kPaperStatedEdges);
  const FilterCharacteristics paper =
      characteriseFilter(presetTaps(FilterPreset::Paper9), kPaperStatedEdges);
  EXPECT_NEAR(fast.delayFrames, 2.0, 1e-9);
  EXPECT_NEAR(fast.delaySpreadFrames, 0.0, 1e-6);
  EXPECT_LT(fast.stopGainMax, paper.stopGainMax);
  EXPECT_GT(fast.halfPowerHz, 5.0);
}

TEST(FirDesign, MinimumPhasePaperKeepsEveryGainWithUnderOneFrameOfDelay) {
  const FirTaps paper = presetTaps(FilterPreset::Paper9);
  const FirTaps minPhase = presetTaps(FilterPreset::MinPhase9);
  for (int i = 0; i <= 100; ++i) {
    EXPECT_NEAR(gainAt(minPhase, 0.005 * i), gainAt(paper, 0.005 * i), 1e-5) << i;
  }
  const FilterCharacteristics c = characteriseFilter(minPhase, kPaperStatedEdges);
  EXPECT_LT(c.delayFrames, 1.0);
  EXPECT_GT(c.delaySpreadFrames, 0.1);  // the price: the phase is not linear
  EXPECT_NEAR(c.jitterRmsGain, characteriseFilter(paper, kPaperStatedEdges).jitterRmsGain, 1e-5);
}

TEST(FirDesign, MinimumPhaseRefusesALeadingZeroTap) {
  EXPECT_FALSE(minimumPhase(FirTaps::normalised(std::array{0.0, 1.0, 1.0}).value()).has_value());
}

TEST(FirDesign, PresetNamesRoundTrip) {
  for (FilterPreset preset : kAllPresets) EXPECT_EQ(presetFromName(presetName(preset)), preset);
  EXPECT_FALSE(presetFromName("paper").has_value());
}

}  // namespace
}  // namespace vem
