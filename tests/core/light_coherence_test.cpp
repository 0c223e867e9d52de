// The coherence measures (core/light_coherence.h): steps match lights by id, skip unlit lights,
// subtract the true motion, and resolve tiny angles; the summary's ranks are the nearest-rank ones.
#include "core/light_coherence.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace vem {
namespace {

glm::vec3 dirAt(double thetaDeg, double phiDeg) {
  const double t = thetaDeg * std::numbers::pi / 180.0;
  const double p = phiDeg * std::numbers::pi / 180.0;
  return glm::vec3(float(std::sin(t) * std::cos(p)), float(std::cos(t)),
                   float(std::sin(t) * std::sin(p)));
}

glm::dmat3 turnAboutUpDeg(double deg) {
  const double c = std::cos(deg * std::numbers::pi / 180.0);
  const double s = std::sin(deg * std::numbers::pi / 180.0);
  return glm::dmat3(glm::dvec3(c, 0.0, s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(-s, 0.0, c));
}

TEST(LightCoherence, StepsMatchLightsByIdNotByPosition) {
  LightSet before{{{0, dirAt(30, 0), glm::vec3(1)}, {1, dirAt(60, 90), glm::vec3(1)}}, 2.0, false};
  // The same lights, listed in the other order, light 1 moved by 10 degrees in theta.
  LightSet after{{{1, dirAt(70, 90), glm::vec3(1)}, {0, dirAt(30, 0), glm::vec3(1)}}, 2.0, false};
  std::vector<double> steps;
  appendAngularStepsDeg(before, after, glm::dmat3(1.0), steps);
  ASSERT_EQ(steps.size(), 2U);
  EXPECT_NEAR(steps[0], 10.0, 1e-4);
  EXPECT_NEAR(steps[1], 0.0, 1e-4);
}

TEST(LightCoherence, UnlitOrNewLightsHaveNoStep) {
  LightSet before{{{0, dirAt(30, 0), glm::vec3(0)}, {1, dirAt(60, 90), glm::vec3(1)}}, 1.0, false};
  LightSet after{{{0, dirAt(120, 0), glm::vec3(1)},
                  {1, dirAt(60, 90), glm::vec3(0)},
                  {7, dirAt(10, 10), glm::vec3(1)}},
                 1.0,
                 false};
  std::vector<double> steps;
  appendAngularStepsDeg(before, after, glm::dmat3(1.0), steps);
  EXPECT_TRUE(steps.empty())
      << "a light unlit in either frame, or new, has no direction to step from";
}

TEST(LightCoherence, TrueMotionIsSubtracted) {
  LightSet before{
      {{0, dirAt(45, 20), glm::vec3(1)}, {1, dirAt(80, 200), glm::vec3(1)}}, 2.0, false};
  LightSet after = before;
  for (Light& l : after.lights) l.dir = glm::vec3(turnAboutUpDeg(3.0) * glm::dvec3(l.dir));
  std::vector<double> withMotion;
  appendAngularStepsDeg(before, after, turnAboutUpDeg(3.0), withMotion);
  std::vector<double> without;
  appendAngularStepsDeg(before, after, glm::dmat3(1.0), without);
  ASSERT_EQ(withMotion.size(), 2U);
  EXPECT_LT(withMotion[0], 1e-4);
  EXPECT_LT(withMotion[1], 1e-4);
  // Without the motion, a light at theta 45 turning 3 degrees in azimuth moves about 2.1 degrees.
  EXPECT_NEAR(without[0], 2.1213, 2e-3);
}

TEST(LightCoherence, TinyStepsAreResolvedNotRoundedToZero) {
  // 0.001 degree: acos of the float dot product would read 0 here.
  LightSet before{{{0, dirAt(40.0, 10.0), glm::vec3(1)}}, 1.0, false};
  LightSet after{{{0, dirAt(40.001, 10.0), glm::vec3(1)}}, 1.0, false};
  std::vector<double> steps;
  appendAngularStepsDeg(before, after, glm::dmat3(1.0), steps);
  ASSERT_EQ(steps.size(), 1U);
  EXPECT_NEAR(steps[0], 0.001, 2e-4);
}

TEST(LightCoherence, SummaryRanksAndLargeFraction) {
  std::vector<double> steps;
  for (int i = 1; i <= 200; ++i) steps.push_back(i / 10.0);  // 0.1 .. 20 degrees
  const StepSummary s = summariseSteps(steps);
  EXPECT_EQ(s.count, 200U);
  EXPECT_DOUBLE_EQ(s.medianDeg, 10.0);  // rank 100
  EXPECT_DOUBLE_EQ(s.p99Deg, 19.8);     // rank 198
  EXPECT_DOUBLE_EQ(s.maxDeg, 20.0);
  EXPECT_DOUBLE_EQ(s.fractionLarge, 150.0 / 200.0);  // 5.1 .. 20
  const StepSummary none = summariseSteps({});
  EXPECT_EQ(none.count, 0U);
  EXPECT_EQ(none.maxDeg, 0.0);
}

}  // namespace
}  // namespace vem
