// vemview's status line (client/vemview/status_text.h, status_line.h): one count per concept,
// rates only over frames drawn, no rate from one frame, the plan once.
#include "client/vemview/status_text.h"

#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "client/scene/primitives.h"
#include "client/vemview/status_line.h"

namespace vem::view {
namespace {

using namespace std::chrono_literals;

// A frame shaded with `diffuse` lights, the first `casters` of them with shadow maps.
render::ShadingLights shadingWith(std::size_t diffuse, std::size_t casters) {
  render::ShadingLights s;
  s.diffuse.lights.resize(diffuse);
  for (std::size_t i = 0; i < casters; ++i) s.shadowDirs.push_back(glm::vec3(0.0F, 1.0F, 0.0F));
  return s;
}

// It said "1.0 frames/s" or "25.7 frames/s" (the window's idle loop) for one drawn frame.
TEST(StatusText, OneDrawnFrameIsOneFrameInItsTimeNotARate) {
  EXPECT_EQ(drawnFramesText(DrawnFrames{1, 1.3, 27.06}), "1 frame in 27.1 ms");
  EXPECT_EQ(drawnFramesText(DrawnFrames{0, 1.0, 0.0}), "no frame drawn");
}

TEST(StatusText, RateIsOverTheFramesDrawnInTheirWallTime) {
  EXPECT_EQ(drawnFramesText(DrawnFrames{12, 4.0, 12 * 80.0}),
            "12 frames, 3.0 frames/s, 80.0 ms each");
}

// Three frames of 22 s each were "0.0 frames/s".
TEST(StatusText, SlowRateKeepsTwoSignificantDigitsNotZero) {
  EXPECT_EQ(drawnFramesText(DrawnFrames{3, 69.77, 3 * 22355.3}),
            "3 frames, 0.043 frames/s, 22355.3 ms each");
}

// The issue asks the composite to show how old its lights are against the picture, and that a
// stopped plate keeps its last picture: both were missing from the status line.
TEST(StatusText, LightAgeAndAStoppedPlateShowInTheStatusLine) {
  LightCounts counts{16, 0, 16, 16, 0, 0.125, "stopped: keeping the last picture"};
  EXPECT_EQ(lightCountsText(counts),
            "lights 16 | shadow maps 16 of 16 | lights 0.125 s older than the picture | plate "
            "stopped: keeping the last picture");
  counts.lightAgeSec = -0.02;
  counts.plateState.clear();
  EXPECT_EQ(lightCountsText(counts),
            "lights 16 | shadow maps 16 of 16 | lights 0.020 s newer than the picture");
}

// A clustered light file said "lights 11 | shadowed 11 | lights 256, shadow maps 64".
TEST(StatusText, ClusteredLightsAreOneNamedCountNotThreeNumbers) {
  const LightCounts counts = lightCountsOf(shadingWith(11, 11), 256, 64);
  EXPECT_EQ(lightCountsText(counts), "lights 256 (11 clusters) | shadow maps 11 of 64");
  EXPECT_EQ(lightCountsText(lightCountsOf(shadingWith(256, 64), 0, 64)),
            "lights 256 | shadow maps 64 of 64");
  EXPECT_EQ(lightCountsText(lightCountsOf(shadingWith(32, 0), 0, 0)), "lights 32 | no shadow maps");
}

TEST(StatusText, SummaryCountsDrawnAndNotRedrawnFrames) {
  const LightCounts counts = lightCountsOf(shadingWith(16, 8), 0, 8);
  EXPECT_EQ(summaryText(DrawnFrames{1, 9.0, 31.0}, 2, counts),
            "1 frame drawn in 31.0 ms, 2 not redrawn (nothing changed) | lights 16 | shadow maps 8 "
            "of 8");
  EXPECT_EQ(
      summaryText(DrawnFrames{3, 1.5, 300.0}, 0, counts),
      "3 frames drawn in 1.50 s (2.0 frames/s, 100.0 ms each) | lights 16 | shadow maps 8 of 8");
}

struct Printed {
  std::vector<std::string> lines;
  StatusLine::Print print() {
    return [this](const std::string& line) { lines.push_back(line); };
  }
};

scene::Scene sphereOnPlane() {
  scene::Scene s;
  s.materials = {scene::Material{}};
  s.meshes = {scene::groundPlane(0.0F, 4.0F), scene::sphereMesh({0, 1, 0}, 0.5F, 16, 32, 0)};
  return s;
}

// Every status line ended with the whole plan ("... | lights 256, shadow maps 64 at 256 px, regions
// on, glossy L/H pass (...), cube map of 128 px (...)").
TEST(StatusLine, PlanIsPrintedOnceNotOnEveryStatusLine) {
  Printed printed;
  const auto t0 = StatusLine::Clock::time_point{};
  StatusLine status(t0, printed.print());
  const RenderPlan plan = planFor(sphereOnPlane(), PlanRequest{});
  const LightCounts counts = lightCountsOf(shadingWith(256, 64), 0, 64);
  status.showPlan(plan);
  for (int second = 1; second <= 3; ++second) {
    status.showPlan(plan);
    status.add(true, 40.0, counts);
    status.add(true, 40.0, counts);
    status.maybePrint(t0 + std::chrono::seconds(second));
  }
  ASSERT_EQ(printed.lines.size(), 4U);
  EXPECT_EQ(printed.lines[0], "plan: " + plan.describe());
  for (std::size_t i = 1; i < printed.lines.size(); ++i) {
    EXPECT_EQ(printed.lines[i],
              "2 frames, 2.0 frames/s, 40.0 ms each | lights 256 | shadow maps 64 of 64");
  }
  PlanRequest fewer;
  fewer.lightCount = 64;
  status.showPlan(planFor(sphereOnPlane(), fewer));  // a changed plan is printed again
  ASSERT_EQ(printed.lines.size(), 5U);
  EXPECT_EQ(printed.lines[4].rfind("plan: lights 64", 0), 0U) << printed.lines[4];
}

// A window shows the same frame again every 15 ms when nothing changes; those are not frames
// drawn, and once nothing is drawn no more lines are printed.
TEST(StatusLine, RateCountsOnlyDrawnFramesNotTheWindowsIdleLoop) {
  Printed printed;
  const auto t0 = StatusLine::Clock::time_point{};
  StatusLine status(t0, printed.print());
  const LightCounts counts = lightCountsOf(shadingWith(11, 11), 256, 64);
  status.add(true, 27.0, counts);
  for (int i = 0; i < 25; ++i) status.add(false, 27.0, counts);
  status.maybePrint(t0 + 1s);
  for (int i = 0; i < 60; ++i) status.add(false, 27.0, counts);
  status.maybePrint(t0 + 2s);
  ASSERT_EQ(printed.lines.size(), 1U);
  EXPECT_EQ(printed.lines[0],
            "1 frame in 27.0 ms | lights 256 (11 clusters) | shadow maps 11 of 64");
  status.printSummary(t0 + 3s, "");
  ASSERT_EQ(printed.lines.size(), 2U);
  EXPECT_EQ(printed.lines[1],
            "1 frame drawn in 27.0 ms, 85 not redrawn (nothing changed) | lights 256 (11 clusters) "
            "| shadow maps 11 of 64");
}

}  // namespace
}  // namespace vem::view
