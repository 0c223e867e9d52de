#include "core/temporal_filter.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/fir_design.h"
#include "core/sphere_points.h"

namespace vem {
namespace {

constexpr double kRateHz = 21.0;

glm::dvec3 chromaOf(std::uint32_t id) {  // a colour of luminance 1, different per light
  const glm::dvec3 c(1.0 + 0.5 * std::sin(double(id)), 1.0, 1.0 + 0.5 * std::cos(double(id)));
  return c / luminance(c);
}

// `count` lights of equal share of `powerSr`, directions wobbling by `motion` around a Fibonacci
// spread. A power of 0 gives a black frame (rgb exactly 0).
LightSet makeFrame(int count, double powerSr, std::uint64_t t, double motion = 0.0) {
  const std::vector<glm::dvec3> base = fibonacciSphere(count);
  LightSet set;
  set.luminanceSr = powerSr;
  set.black = powerSr == 0.0;
  for (int i = 0; i < count; ++i) {
    const double phase = 0.9 * double(t) + 1.7 * i;
    const glm::dvec3 wobble(std::sin(phase), std::cos(1.3 * phase), std::sin(0.4 * phase + i));
    const auto id = std::uint32_t(i);
    set.lights.push_back({id, glm::vec3(glm::normalize(base[std::size_t(i)] + motion * wobble)),
                          glm::vec3(powerSr / count * chromaOf(id))});
  }
  return set;
}

LightSet firstLights(const LightSet& set, std::size_t k) {
  LightSet prefix = set;
  prefix.lights.resize(k);
  return prefix;
}

void expectSameSet(const LightSet& a, const LightSet& b) {
  EXPECT_EQ(a.luminanceSr, b.luminanceSr);
  EXPECT_EQ(a.black, b.black);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].id, b.lights[i].id);
    EXPECT_EQ(a.lights[i].dir, b.lights[i].dir) << "light " << i;
    EXPECT_EQ(a.lights[i].rgb, b.lights[i].rgb) << "light " << i;
  }
}

double totalLuminance(const LightSet& set) {
  double sum = 0.0;
  for (const Light& light : set.lights) sum += luminance(light.rgb);
  return sum;
}

// Frame `seq` of a test sequence: four moving lights, a power that varies.
LightSet movingFrame(std::uint64_t seq) { return makeFrame(4, 1.0 + double(seq % 5), seq, 0.5); }

void feed(TemporalFilter& filter, std::uint64_t fromSeq, std::uint64_t toSeq) {
  for (std::uint64_t seq = fromSeq; seq < toSeq; ++seq) (void)filter.push(seq, movingFrame(seq));
}

LightSet pushOk(TemporalFilter& filter, std::uint64_t seq, const LightSet& frame) {
  FilterResult result = filter.push(seq, frame);
  EXPECT_TRUE(result.lights.has_value()) << "seq " << seq;
  return result.lights.value_or(LightSet{});
}

// Running sums of the taps: the filter's response to a unit step, frame by frame.
std::vector<double> stepResponse(const FirTaps& taps) {
  std::vector<double> step;
  double sum = 0.0;
  for (double w : taps.weights()) step.push_back(sum += w);
  return step;
}

TEST(TemporalFilter, StaticInputGivesIdenticalLightsEveryFrame) {
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  const LightSet frame = makeFrame(16, 3.0, 0);
  const LightSet first = pushOk(filter, 0, frame);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(first.lights[5].dir[c], frame.lights[5].dir[c], 1e-6);
    EXPECT_NEAR(first.lights[5].rgb[c], frame.lights[5].rgb[c], 1e-6);
  }
  for (std::uint64_t seq = 1; seq < 30; ++seq) expectSameSet(pushOk(filter, seq, frame), first);
}

TEST(TemporalFilter, ConstantPowerIsPreservedByEveryPreset) {
  for (FilterPreset preset : kAllPresets) {
    TemporalFilter filter(presetTaps(preset));
    for (std::uint64_t seq = 0; seq < 25; ++seq) {
      const LightSet out = pushOk(filter, seq, makeFrame(8, 2.5, seq, 0.4));
      EXPECT_NEAR(out.luminanceSr, 2.5, 1e-12) << presetName(preset);
      EXPECT_NEAR(totalLuminance(out), 2.5, 1e-5) << presetName(preset);
    }
  }
}

TEST(TemporalFilter, StepFromSequenceZeroFollowsTheStepResponseAndSettlesAfterKFrames) {
  for (FilterPreset preset : kAllPresets) {
    const FirTaps taps = presetTaps(preset);
    const std::vector<double> step = stepResponse(taps);
    TemporalFilter filter(taps);
    constexpr std::uint64_t kStepSeq = 3;  // early, so the ring's history reaches before seq 0
    for (std::uint64_t seq = 0; seq < kStepSeq + taps.size() + 3; ++seq) {
      const LightSet out = pushOk(filter, seq, makeFrame(4, seq < kStepSeq ? 1.0 : 3.0, seq));
      const std::size_t j =
          seq < kStepSeq ? 0 : std::min<std::size_t>(seq - kStepSeq + 1, step.size());
      const double expected = seq < kStepSeq ? 1.0 : 1.0 + 2.0 * step[j - 1];
      EXPECT_NEAR(out.luminanceSr, expected, 1e-12) << presetName(preset) << " seq " << seq;
    }
  }
}

TEST(TemporalFilter, OutputDoesNotDependOnTheFirstSequenceNumber) {
  TemporalFilter fromZero(presetTaps(FilterPreset::Paper9));
  TemporalFilter fromLarge(presetTaps(FilterPreset::Paper9));
  constexpr std::uint64_t kOffset = 1'000'000'007;
  for (std::uint64_t t = 0; t < 20; ++t) {
    expectSameSet(pushOk(fromLarge, kOffset + t, movingFrame(t)),
                  pushOk(fromZero, t, movingFrame(t)));
  }
}

// Steady-state amplitude of power 1 + 0.5 sin(2 pi f t / rate), by projection on whole periods.
double sinusoidGain(FilterPreset preset, double freqHz) {
  TemporalFilter filter(presetTaps(preset));
  const auto power = [&](std::uint64_t t) {
    return 1.0 + 0.5 * std::sin(2.0 * std::numbers::pi * freqHz * double(t) / kRateHz);
  };
  double sinPart = 0.0;
  double cosPart = 0.0;
  constexpr std::uint64_t kSkip = 21;
  constexpr std::uint64_t kFrames = 4 * 21;  // whole periods of 1 Hz and 10 Hz at 21 Hz
  for (std::uint64_t t = 0; t < kSkip + kFrames; ++t) {
    const double out = pushOk(filter, t, makeFrame(2, power(t), t)).luminanceSr - 1.0;
    if (t < kSkip) continue;
    const double phase = 2.0 * std::numbers::pi * freqHz * double(t) / kRateHz;
    sinPart += out * std::sin(phase);
    cosPart += out * std::cos(phase);
  }
  return std::hypot(sinPart, cosPart) * 2.0 / double(kFrames) / 0.5;
}

TEST(TemporalFilter, OneHertzPowerPassesAndTenHertzIsStopped) {
  const FirTaps paper = presetTaps(FilterPreset::Paper9);
  const double low = sinusoidGain(FilterPreset::Paper9, 1.0);
  const double high = sinusoidGain(FilterPreset::Paper9, 10.0);
  EXPECT_NEAR(low, gainAt(paper, 1.0 / kRateHz), 1e-9);
  EXPECT_NEAR(high, gainAt(paper, 10.0 / kRateHz), 1e-9);
  EXPECT_GT(low, 0.9);
  EXPECT_LT(high, 0.1);
  EXPECT_NEAR(sinusoidGain(FilterPreset::None, 10.0), 1.0, 1e-9);
}

// RMS of the filtered direction's offset from +Y per unit RMS of white offsets fed in.
double measuredJitterGain(FilterPreset preset) {
  TemporalFilter filter(presetTaps(preset));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> offset(0.0, 1e-3);  // radians, small: normalise is ~linear
  double inSquares = 0.0;
  double outSquares = 0.0;
  for (std::uint64_t seq = 0; seq < 20000; ++seq) {
    const glm::dvec3 in(offset(rng), 1.0, offset(rng));
    LightSet frame;
    frame.luminanceSr = 1.0;
    frame.lights = {{0, glm::vec3(glm::normalize(in)), glm::vec3(1.0F)}};
    const glm::dvec3 out(pushOk(filter, seq, frame).lights[0].dir);
    if (seq < 20) continue;  // past the start, whose history is one frame repeated
    inSquares += in.x * in.x + in.z * in.z;
    outSquares += out.x * out.x + out.z * out.z;
  }
  return std::sqrt(outSquares / inSquares);
}

TEST(TemporalFilter, WhiteDirectionJitterShrinksByTheTapsRmsGain) {
  for (FilterPreset preset : kAllPresets) {
    const double predicted =
        characteriseFilter(presetTaps(preset), {kRateHz, 7.0, 9.0}).jitterRmsGain;
    EXPECT_NEAR(measuredJitterGain(preset), predicted, 0.02 * predicted) << presetName(preset);
  }
}

TEST(TemporalFilter, PowerAfterASuddenDropIsClampedAtZeroNotNegative) {
  const FirTaps taps = presetTaps(FilterPreset::Paper9);
  const std::vector<double> step = stepResponse(taps);
  TemporalFilter filter(taps);
  for (std::uint64_t seq = 0; seq < 10; ++seq) (void)filter.push(seq, makeFrame(3, 1.0, seq));
  bool clamped = false;
  for (std::uint64_t j = 0; j < taps.size(); ++j) {
    const LightSet out = pushOk(filter, 10 + j, makeFrame(3, 0.0, 10 + j));
    const double unclamped = 1.0 - step[j];
    EXPECT_NEAR(out.luminanceSr, std::max(0.0, unclamped), 1e-12) << "frame " << j;
    EXPECT_EQ(out.black, out.luminanceSr == 0.0);
    clamped = clamped || unclamped < 0.0;
  }
  EXPECT_TRUE(clamped);  // the paper's negative taps do undershoot
}

TEST(TemporalFilter, DuplicateSeqReplacesTheNewestFrame) {
  TemporalFilter withDuplicate(presetTaps(FilterPreset::Paper9));
  TemporalFilter clean(presetTaps(FilterPreset::Paper9));
  feed(withDuplicate, 0, 6);
  feed(clean, 0, 5);
  const FilterResult replaced = withDuplicate.push(5, movingFrame(12));
  EXPECT_EQ(replaced.event, FrameEvent::DuplicateReplaced);
  ASSERT_TRUE(replaced.lights.has_value());
  expectSameSet(*replaced.lights, pushOk(clean, 5, movingFrame(12)));
}

TEST(TemporalFilter, GapShorterThanKHoldsTheLastFrame) {
  const FirTaps taps = presetTaps(FilterPreset::Paper9);
  for (std::uint64_t missed : {std::uint64_t{2}, std::uint64_t{taps.size() - 1}}) {
    TemporalFilter gapped(taps);
    TemporalFilter held(taps);
    feed(gapped, 0, 3);
    feed(held, 0, 3);
    const std::uint64_t next = 3 + missed;
    for (std::uint64_t seq = 3; seq < next; ++seq) (void)held.push(seq, movingFrame(2));
    const FilterResult afterGap = gapped.push(next, movingFrame(next));
    EXPECT_EQ(afterGap.event, FrameEvent::GapHeld);
    EXPECT_EQ(afterGap.missedFrames, missed);
    ASSERT_TRUE(afterGap.lights.has_value());
    expectSameSet(*afterGap.lights, pushOk(held, next, movingFrame(next)));
  }
}

TEST(TemporalFilter, GapOfKFramesResets) {
  const FirTaps taps = presetTaps(FilterPreset::Paper9);
  TemporalFilter filter(taps);
  feed(filter, 0, 10);
  const FilterResult reset = filter.push(10 + taps.size(), movingFrame(3));
  EXPECT_EQ(reset.event, FrameEvent::ResetAfterGap);
  EXPECT_EQ(reset.missedFrames, taps.size());
  ASSERT_TRUE(reset.lights.has_value());
  TemporalFilter fresh(taps);
  expectSameSet(*reset.lights, pushOk(fresh, 0, movingFrame(3)));
}

TEST(TemporalFilter, StaleSeqIsRejectedAndChangesNothing) {
  TemporalFilter withStale(presetTaps(FilterPreset::Paper9));
  TemporalFilter clean(presetTaps(FilterPreset::Paper9));
  feed(withStale, 0, 6);
  feed(clean, 0, 6);
  const FilterResult stale = withStale.push(3, movingFrame(40));
  EXPECT_EQ(stale.event, FrameEvent::StaleRejected);
  EXPECT_FALSE(stale.lights.has_value());
  expectSameSet(pushOk(withStale, 6, movingFrame(6)), pushOk(clean, 6, movingFrame(6)));
}

TEST(TemporalFilter, FirstKLightsFilterToTheFirstKOfTheFilteredSet) {
  constexpr int kCount = 32;
  // Moving lights, varying power, two black frames, a duplicate, a held gap.
  const std::vector<std::uint64_t> seqs = {0, 1, 2, 3, 3, 4, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  for (std::size_t k : {1U, 5U, 17U}) {
    TemporalFilter all(presetTaps(FilterPreset::Paper9));
    TemporalFilter prefix(presetTaps(FilterPreset::Paper9));
    for (std::uint64_t seq : seqs) {
      const double power = (seq == 8 || seq == 9) ? 0.0 : 1.0 + 0.7 * std::sin(double(seq));
      const LightSet frame = makeFrame(kCount, power, seq, 0.6);
      const LightSet full = pushOk(all, seq, frame);
      expectSameSet(pushOk(prefix, seq, firstLights(frame, k)), firstLights(full, k));
    }
  }
}

TEST(TemporalFilter, GrowingTheLightCountDoesNotPop) {
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  const LightSet small = makeFrame(8, 2.0, 0);
  LightSet before;
  for (std::uint64_t seq = 0; seq < 12; ++seq) before = pushOk(filter, seq, small);
  LightSet grown = makeFrame(16, 2.0, 0);
  std::copy(small.lights.begin(), small.lights.end(), grown.lights.begin());  // ids 0-7 stay put
  for (std::size_t i = 0; i < 16; ++i)
    grown.lights[i].rgb = glm::vec3(2.0 / 16 * chromaOf(std::uint32_t(i)));
  const LightSet after = pushOk(filter, 12, grown);
  EXPECT_EQ(after.luminanceSr, before.luminanceSr);
  EXPECT_NEAR(totalLuminance(after), 2.0, 1e-5);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(after.lights[i].dir, before.lights[i].dir) << i;
  for (std::size_t i = 8; i < 16; ++i) {  // new lights start where they are, not at a default
    EXPECT_GT(glm::dot(after.lights[i].dir, grown.lights[i].dir), 1.0F - 1e-6F) << i;
  }
}

TEST(TemporalFilter, LightAbsentForKFramesRestartsAtItsCurrentDirection) {
  const FirTaps taps = presetTaps(FilterPreset::Paper9);
  for (std::uint64_t absent : {std::uint64_t{taps.size() - 1}, std::uint64_t{taps.size()}}) {
    TemporalFilter filter(taps);
    for (std::uint64_t seq = 0; seq < 10; ++seq) (void)filter.push(seq, makeFrame(4, 1.0, 0));
    for (std::uint64_t seq = 10; seq < 10 + absent; ++seq)
      (void)filter.push(seq, makeFrame(2, 1.0, 0));
    LightSet back = makeFrame(4, 1.0, 0);
    back.lights[3].dir = -back.lights[3].dir;  // it returns somewhere else
    const LightSet out = pushOk(filter, 10 + absent, back);
    const float agreement = glm::dot(out.lights[3].dir, back.lights[3].dir);
    if (absent >= taps.size()) {
      EXPECT_GT(agreement, 1.0F - 1e-6F) << "restarted";
    } else {
      EXPECT_LT(agreement, 0.0F) << "held: the newest frame weighs only w0";
    }
  }
}

TEST(TemporalFilter, AntipodalFlipGivesFiniteUnitVectors) {
  TemporalFilter average(FirTaps::normalised(std::array{1.0, 1.0}).value());
  LightSet up = makeFrame(1, 1.0, 0);
  LightSet down = up;
  down.lights[0].dir = -up.lights[0].dir;
  (void)average.push(0, up);
  const LightSet cancelled = pushOk(average, 1, down);  // the mean is exactly 0
  EXPECT_GT(glm::dot(cancelled.lights[0].dir, down.lights[0].dir), 1.0F - 1e-6F);  // the newest

  TemporalFilter paper(presetTaps(FilterPreset::Paper9));
  for (std::uint64_t seq = 0; seq < 20; ++seq) {
    const glm::vec3 dir = pushOk(paper, seq, seq % 3 == 0 ? up : down).lights[0].dir;
    EXPECT_TRUE(std::isfinite(dir.x) && std::isfinite(dir.y) && std::isfinite(dir.z)) << seq;
    EXPECT_NEAR(glm::length(dir), 1.0F, 1e-6F) << seq;
  }
}

TEST(TemporalFilter, BlackFramesHoldDirectionAndColourWhileThePowerDecays) {
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  LightSet lit;
  for (std::uint64_t seq = 0; seq < 10; ++seq) lit = pushOk(filter, seq, makeFrame(3, 2.0, 0));
  LightSet black = makeFrame(3, 0.0, 0);
  for (Light& light : black.lights) light.dir = glm::vec3(0.0F, -1.0F, 0.0F);  // meaningless
  const LightSet firstBlack = pushOk(filter, 10, black);
  EXPECT_GT(firstBlack.luminanceSr, 0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(firstBlack.lights[i].dir, lit.lights[i].dir);
    const glm::vec3 ratio = firstBlack.lights[i].rgb / lit.lights[i].rgb;
    EXPECT_NEAR(ratio.x, ratio.y, 1e-5F);
    EXPECT_NEAR(ratio.z, ratio.y, 1e-5F);
  }
  LightSet last;
  for (std::uint64_t seq = 11; seq < 19; ++seq) last = pushOk(filter, seq, black);
  EXPECT_TRUE(last.black);
  EXPECT_EQ(last.lights[1].rgb, glm::vec3(0.0F));
  EXPECT_EQ(last.lights[1].dir, lit.lights[1].dir);
}

TEST(TemporalFilter, LightsFirstSeenInABlackFrameStayDarkSoNoPowerIsAdded) {
  TemporalFilter filter(presetTaps(FilterPreset::Paper9));
  for (std::uint64_t seq = 0; seq < 10; ++seq) (void)filter.push(seq, makeFrame(4, 2.0, seq));
  const LightSet out = pushOk(filter, 10, makeFrame(8, 0.0, 10));  // the count grew while black
  ASSERT_GT(out.luminanceSr, 0.0);
  EXPECT_NEAR(totalLuminance(out), out.luminanceSr, 1e-5);
  EXPECT_EQ(out.lights[6].rgb, glm::vec3(0.0F));
}

TEST(TemporalFilter, DelayIsTheDcGroupDelayOfTheTaps) {
  EXPECT_NEAR(TemporalFilter(presetTaps(FilterPreset::Paper9)).delayFrames(), 4.0, 1e-12);
  EXPECT_NEAR(TemporalFilter(presetTaps(FilterPreset::Equiripple5)).delayFrames(), 2.0, 1e-9);
  EXPECT_EQ(TemporalFilter(presetTaps(FilterPreset::None)).delayFrames(), 0.0);
  EXPECT_LT(TemporalFilter(presetTaps(FilterPreset::MinPhase9)).delayFrames(), 1.0);
}

}  // namespace
}  // namespace vem
