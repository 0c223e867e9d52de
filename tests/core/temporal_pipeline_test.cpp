// The light pipeline over time (sampler, then the temporal filter): a static map gives identical
// lights every frame; a map turning one degree per frame gives small per-light steps with stable
// identities; and the progressive prefix survives filtering.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/temporal_filter.h"
#include "support/test_maps.h"

namespace vem {
namespace {

double angleDeg(glm::vec3 a, glm::vec3 b) {
  return 2 * std::asin(std::min(1.0, 0.5 * double(glm::length(a - b)))) * 180 / std::numbers::pi;
}

LightSet lightsOf(const EnvMap& map, std::size_t count, SamplerKind kind) {
  return generateLights(buildSamplingTables(map),
                        defaultSamplingPattern(map.layout).first(count), kind);
}

TEST(TemporalPipeline, StaticMapGivesIdenticalLightsEveryFrame) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 360, 90);
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  const LightSet raw = lightsOf(map, 300, SamplerKind::Havran);
  const LightSet first = *filter.push(0, raw).lights;
  for (std::uint64_t seq = 1; seq < 20; ++seq) {
    const LightSet now = *filter.push(seq, lightsOf(map, 300, SamplerKind::Havran)).lights;
    ASSERT_EQ(now.lights.size(), first.lights.size());
    for (std::size_t i = 0; i < now.lights.size(); ++i) {
      ASSERT_EQ(now.lights[i].id, first.lights[i].id);
      ASSERT_EQ(now.lights[i].dir, first.lights[i].dir) << "frame " << seq << " light " << i;
      ASSERT_EQ(now.lights[i].rgb, first.lights[i].rgb) << "frame " << seq << " light " << i;
    }
  }
}

struct StepStatistics {
  double medianDeg = 0;
  double p99Deg = 0;
  double maxDeg = 0;
};

// Steps of each filtered light between consecutive frames while the map turns one column a frame
// (360 / W degrees), after the filter has filled its history.
StepStatistics stepsUnderRotation(const EnvMap& map, SamplerKind kind, std::size_t count,
                                  std::uint64_t frames) {
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  std::vector<double> steps;
  LightSet previous;
  for (std::uint64_t seq = 0; seq < frames; ++seq) {
    const LightSet now =
        *filter.push(seq, lightsOf(testing::rotatedColumns(map, int(seq)), count, kind)).lights;
    if (seq > 9) {
      for (std::size_t i = 0; i < now.lights.size(); ++i) {
        EXPECT_EQ(now.lights[i].id, previous.lights[i].id);
        steps.push_back(angleDeg(now.lights[i].dir, previous.lights[i].dir));
      }
    }
    previous = now;
  }
  std::sort(steps.begin(), steps.end());
  return {steps[steps.size() / 2], steps[steps.size() * 99 / 100], steps.back()};
}

TEST(TemporalPipeline, MapTurningOneDegreePerFrameMovesLightsBySmallContinuousSteps) {
  // A turning map shifts each row's cumulative table by the mass that crosses the table's origin,
  // so a light in a dim stretch can move several times faster than the map while a bright region
  // crosses the origin (paper 004, 3.3: "the direction of virtually all light sources may change").
  // What must hold: steps are bounded, typical steps are about the map's own motion, and they
  // shrink in proportion when the map turns slower (continuity in time: no jumps).
  const EnvMap oneDegree = testing::proceduralSky(MapLayout::Hemisphere, 360, 90);
  const EnvMap quarterDegree = testing::proceduralSky(MapLayout::Hemisphere, 1440, 90);
  // Both turn by 50 degrees, so the glow crosses the tables' origin (at 323 degrees) in both.
  const StepStatistics fast = stepsUnderRotation(oneDegree, SamplerKind::Havran, 256, 60);
  const StepStatistics slow = stepsUnderRotation(quarterDegree, SamplerKind::Havran, 256, 210);
  std::printf(
      "filtered steps per frame (deg): 1 deg/frame median %.2f p99 %.2f max %.2f; "
      "0.25 deg/frame median %.2f p99 %.2f max %.2f\n",
      fast.medianDeg, fast.p99Deg, fast.maxDeg, slow.medianDeg, slow.p99Deg, slow.maxDeg);
  EXPECT_LT(fast.medianDeg, 1.5);
  EXPECT_LT(fast.maxDeg, 20.0);
  EXPECT_LT(slow.maxDeg, 0.4 * fast.maxDeg);
  EXPECT_LT(slow.medianDeg, 0.4 * fast.medianDeg);
}

TEST(TemporalPipeline, FirstKFilteredLightsAreTheFilteredKSet) {
  const EnvMap map = testing::proceduralSky(MapLayout::Sphere, 256, 128);
  TemporalFilter all(presetTaps(FilterPreset::Paper9));
  TemporalFilter some(presetTaps(FilterPreset::Paper9));
  for (std::uint64_t seq = 0; seq < 12; ++seq) {
    const EnvMap frame = testing::rotatedColumns(map, int(3 * seq));
    const SamplingTables tables = buildSamplingTables(frame);
    const auto pattern = defaultSamplingPattern(frame.layout);
    const LightSet many =
        *all.push(seq, generateLights(tables, pattern.first(500), SamplerKind::Havran))
             .lights;
    const LightSet few =
        *some.push(seq, generateLights(tables, pattern.first(50), SamplerKind::Havran))
             .lights;
    for (std::size_t i = 0; i < few.lights.size(); ++i) {
      ASSERT_EQ(few.lights[i].dir, many.lights[i].dir) << "frame " << seq << " light " << i;
      // The luminance share scales with 500 / 50 (the colour is each set's own cell's).
      ASSERT_NEAR(luminance(few.lights[i].rgb), 10.0 * luminance(many.lights[i].rgb),
                  1e-5 * luminance(few.lights[i].rgb));
    }
  }
}

}  // namespace
}  // namespace vem
