// The coherence study (synth/coherence_study.h): a still map gives still lights, the sums are the
// documented ones, noise makes the lights flicker and the temporal filter takes some of that away,
// and a turn is subtracted from the steps.
#include "synth/coherence_study.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/color.h"
#include "core/sampling_tables.h"
#include "core/sphere_points.h"
#include "support/test_maps.h"

namespace vem::synth {
namespace {

struct Measured {
  CoherenceFigures figures;
  CoherenceTally tally;
};

Measured measure(const std::vector<SequenceFrame>& frames, SamplerKind sampler, FilterPreset preset,
                 std::size_t lights) {
  const auto normals = fibonacciSphere(64);
  const auto exact = exactIrradiance(frames, normals);
  const auto sets = filterSequence(sampleSequence(frames, sampler, lights), preset);
  CoherenceTally t = tallySequence(frames, sets, exact, normals);
  return {summarise(t), std::move(t)};
}

TEST(CoherenceStudy, StillMapGivesStillLightsAndNoFlicker) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 128, 32);
  const auto frames = noisySequence(map, 0.0, 5, 1);
  for (SamplerKind sampler : {SamplerKind::Havran, SamplerKind::Standard}) {
    const Measured m = measure(frames, sampler, FilterPreset::None, 64);
    EXPECT_EQ(m.figures.steps.count, 4U * 64U) << "every light of every frame pair has a step";
    EXPECT_EQ(m.figures.steps.maxDeg, 0.0);
    EXPECT_EQ(m.figures.lightsFlicker, 0.0);
    EXPECT_EQ(m.figures.excessFlicker, 0.0);
    EXPECT_GT(m.figures.meanError, 0.0);
    EXPECT_LT(m.figures.meanError, 0.1);
  }
}

TEST(CoherenceStudy, FlickerSumsAreTheDocumentedOnes) {
  // One normal straight up, a constant map, and one light straight up whose luminance goes 1, 2, 1.
  const EnvMap map = EnvMap::filled(MapLayout::Hemisphere, 64, 16, glm::vec3(1.0F));
  const std::vector<SequenceFrame> frames(3, SequenceFrame{map, glm::dmat3(1.0)});
  const std::vector<glm::dvec3> normals{{0.0, 1.0, 0.0}};
  const auto exact = exactIrradiance(frames, normals);
  std::vector<LightSet> sets;
  for (float y : {1.0F, 2.0F, 1.0F})
    sets.push_back({{{0, glm::vec3(0, 1, 0), glm::vec3(y)}}, y, false});
  const CoherenceTally t = tallySequence(frames, sets, exact, normals);
  EXPECT_DOUBLE_EQ(t.lightsChangeSq, 2.0);
  EXPECT_DOUBLE_EQ(t.exactChangeSq, 0.0);
  EXPECT_DOUBLE_EQ(t.excessChangeSq, 2.0);
  const double e = exact[0][0].y;  // about pi for radiance 1
  EXPECT_NEAR(e, std::numbers::pi, 0.01);
  EXPECT_NEAR(t.exactSq, 2 * e * e, 1e-9);
  EXPECT_EQ(t.frames, 3U);
  EXPECT_NEAR(summarise(t).lightsFlicker, 1.0 / e, 1e-12);
}

TEST(CoherenceStudy, NoiseFlickersTheLightsAndTheFilterSmoothsIt) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 128, 32);
  const auto frames = noisySequence(map, 0.03, 20, 3);
  const Measured raw = measure(frames, SamplerKind::Havran, FilterPreset::None, 64);
  const Measured filtered = measure(frames, SamplerKind::Havran, FilterPreset::Paper9, 64);
  EXPECT_GT(raw.figures.steps.medianDeg, 0.0);
  // 3 % noise per pixel moves the exact irradiance too (about 0.14 % per frame over these 4096
  // pixels); the lights, each a point of the noisy density, move at least as much.
  EXPECT_GT(raw.figures.exactFlicker, 0.0);
  EXPECT_GE(raw.figures.lightsFlicker, raw.figures.exactFlicker);
  EXPECT_GT(raw.figures.excessFlicker, 0.0);
  // The filter averages each light over 9 frames: smaller steps, less flicker.
  EXPECT_LT(filtered.figures.lightsFlicker, 0.8 * raw.figures.lightsFlicker);
  EXPECT_LT(filtered.figures.steps.medianDeg, raw.figures.steps.medianDeg);
}

TEST(CoherenceStudy, SmoothedImportanceHoldsTheLightsStillAndKeepsTheNewestPower) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 128, 32);
  const auto frames = noisySequence(map, 0.03, 12, 5);
  const auto normals = fibonacciSphere(64);
  const auto exact = exactIrradiance(frames, normals);
  const auto raw = sampleSequence(frames, SamplerKind::Havran, 64);
  const auto smoothed = sampleSequence(frames, SamplerKind::Havran, 64, 0.25);
  const CoherenceFigures rawFigures = summarise(tallySequence(frames, raw, exact, normals));
  const CoherenceFigures smoothFigures = summarise(tallySequence(frames, smoothed, exact, normals));
  EXPECT_LT(smoothFigures.steps.medianDeg, 0.6 * rawFigures.steps.medianDeg);
  // The power is the newest map's, not the average's.
  for (std::size_t k = 0; k < frames.size(); ++k) {
    double sum = 0.0;
    for (const Light& light : smoothed[k].lights) sum += luminance(light.rgb);
    EXPECT_NEAR(sum / luminance(radianceIntegralSr(frames[k].map)), 1.0, 1e-5) << "frame " << k;
  }
}

// Catches a gate that does not open: an ungated moving average drags a light switching on behind
// (its lights stay where the average's power is, not where the newest map's is), which the
// gated one must not, while it still averages the noise of a map at rest away.
TEST(CoherenceStudy, GatedSmoothingFollowsALightSwitchingOnAndStillHoldsARestingMapStill) {
  const EnvMap sky = testing::proceduralSky(MapLayout::Hemisphere, 128, 32);
  const auto normals = fibonacciSphere(64);
  const auto figures = [&](const std::vector<SequenceFrame>& frames, double weight, double gate) {
    const auto exact = exactIrradiance(frames, normals);
    return summarise(
        tallySequence(frames, sampleSequence(frames, SamplerKind::Havran, 64, weight, gate), exact,
                      normals));
  };
  // A sun: a hot pixel holding most of the power, switching on.
  const EnvMap sun = testing::hotPixelMap(MapLayout::Hemisphere, 128, 32, 40, 12, 1e4F, 1.0F);
  const auto switching = switchOnSequence(sun, 20);
  // Measured: error 2.88 % unsmoothed, 8.08 % averaged, 2.88 % gated; median step at rest
  // 0.087 degree unsmoothed, 0.017 gated.
  const CoherenceFigures raw = figures(switching, 1.0, 0.0);
  const CoherenceFigures dragged = figures(switching, 0.25, 0.0);
  const CoherenceFigures gated = figures(switching, 0.25, 0.1);
  EXPECT_GT(dragged.meanError, 1.3 * raw.meanError);
  EXPECT_LT(gated.meanError, 1.1 * raw.meanError);

  const auto resting = noisySequence(sky, 0.03, 12, 5);
  const CoherenceFigures restingRaw = figures(resting, 1.0, 0.0);
  const CoherenceFigures restingGated = figures(resting, 0.25, 0.1);
  EXPECT_LT(restingGated.steps.medianDeg, 0.6 * restingRaw.steps.medianDeg);
}

// The local lift (an experiment, docs/temporal-filter.md): a dark pixel beside a bright one rises
// to the fraction of the mean around it, wrapping across the seam; where the map is even, nothing
// changes; a bright pixel is never lowered.
TEST(CoherenceStudy, LiftRaisesADarkPixelToTheFractionOfItsNeighbourhoodAndLeavesAnEvenMap) {
  const int width = 16, height = 8;
  EnvMap map = EnvMap::filled(MapLayout::Hemisphere, width, height, glm::vec3(0.0F));
  map.set(0, 4, glm::vec3(90.0F));  // luminance 90 at the seam
  const EnvMap lifted = liftImportance(map, 0.5, 1);
  // Radius 1: a 3 x 3 box holding the bright pixel has mean 10; half of that is 5.
  EXPECT_NEAR(luminance(glm::dvec3(lifted.at(width - 1, 4))), 5.0, 1e-4);  // across the seam
  EXPECT_NEAR(luminance(glm::dvec3(lifted.at(1, 3))), 5.0, 1e-4);
  EXPECT_EQ(lifted.at(3, 4), glm::vec3(0.0F));  // outside the box
  EXPECT_EQ(lifted.at(0, 4), glm::vec3(90.0F));  // the bright pixel itself
  const EnvMap even = EnvMap::filled(MapLayout::Hemisphere, width, height, glm::vec3(2.0F));
  EXPECT_EQ(liftImportance(even, 0.5, 2).rgb, even.rgb);
}

TEST(CoherenceStudy, TurningMapStepsAreMeasuredBeyondTheTurn) {
  // A hot pixel holding most of the power: most lights stand on it and turn with it. One column
  // per frame is an exact turn of 2.8125 degrees.
  const EnvMap map = testing::hotPixelMap(MapLayout::Hemisphere, 128, 32, 40, 12, 1e4F, 1.0F);
  const auto frames = turningSequence(map, 360.0 / 128, 6);
  for (SamplerKind sampler : {SamplerKind::Havran, SamplerKind::Standard}) {
    const Measured m = measure(frames, sampler, FilterPreset::None, 64);
    // Beyond the turn those lights hold still; counted without it, they would step about
    // 2.8 sin(theta) = 1.6 degrees at the pixel's theta of 35 degrees.
    EXPECT_LT(m.figures.steps.medianDeg, 0.1) << samplerName(sampler);
    EXPECT_GT(m.figures.exactFlicker, 0.01) << "the hot pixel's turn changes the irradiance";
  }
}

}  // namespace
}  // namespace vem::synth
